// URScript programs: the controller evaluates the plan's cubic Hermite pieces itself, every
// servo period, and streams them with servoj; gripper commands go to the Robotiq URCap's rq_*
// functions; synchronisation points wait for the other robots through a socket.
#include <algorithm>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/number_text.h"
#include "tools/export/plan_export.h"
#include "tools/export/robotiq.h"

namespace dashbed::exporting {
namespace {

constexpr const char* kSocket = "dashbed_sync";
/// How long a synchronisation point waits for the others [s].
constexpr int kSyncTimeout = 600;

std::string num(double x) { return core::fixedText(x, 9); }

std::string list(const core::Vector6& v) {
  std::string text = "[";
  for (int j = 0; j < 6; ++j) text += (j ? ", " : "") + num(v[j]);
  return text + "]";
}

/// Something that happens at a plan time besides following the curve.
struct Event {
  double t;
  int order;  // ties: synchronisation before gripper commands
  std::string code;
};

std::vector<Event> eventsOf(const RobotTimeline& robot, const std::string& function) {
  std::vector<Event> events;
  for (const SyncPoint& sync : robot.syncs) {
    std::ostringstream code;
    code << "  # synchronisation " << sync.index << ": " << sync.why << " at t = " << num(sync.t) << " s\n"
         << "  socket_send_line(\"" << robot.robot << " " << sync.index << "\", \"" << kSocket << "\")\n"
         << "  dashbed_go = socket_read_ascii_float(1, \"" << kSocket << "\", " << kSyncTimeout << ")\n"
         << "  if dashbed_go[0] != 1 or dashbed_go[1] != " << sync.index << ":\n"
         << "    popup(\"" << function << ": synchronisation " << sync.index << " failed\", \"dashbed\", error=True)\n"
         << "    halt\n"
         << "  end\n";
    events.push_back({sync.t, 0, code.str()});
  }
  for (const GripperStep& g : robot.gripper) {
    std::ostringstream code;
    code << "  # gripper " << (g.action == core::GripperAction::kClose ? "close" : "open") << ": opening "
         << core::significantText(g.position * 1000.0, 4) << " mm, " << core::significantText(g.speed * 1000.0, 4)
         << " mm/s, " << core::significantText(g.force, 4) << " N\n"
         << "  rq_set_force(" << robotiqForce(g.force) << ")\n"
         << "  rq_set_speed(" << robotiqSpeed(g.speed) << ")\n"
         << "  rq_move(" << robotiqPosition(g.position) << ")\n";
    events.push_back({g.t, 1, code.str()});
  }
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
    return a.t < b.t || (a.t == b.t && a.order < b.order);
  });
  return events;
}

std::string program(const ExportTimeline& timeline, const RobotTimeline& robot, const ExportOptions& o) {
  const std::string function = "dashbed_" + robot.robot;
  const std::string servo = ", 0, 0, " + num(o.servo_period) + ", " + num(o.lookahead) + ", " + num(o.gain) + ")";
  std::ostringstream out;
  out << "# dashbed URScript program for robot " << robot.robot << " of world " << timeline.world << "\n";
  for (const std::string& line : o.header) out << "# " << line << "\n";
  out << "# Follows the plan's curve (cubic Hermite pieces between the plan's points), evaluated every "
      << num(o.servo_period) << " s\n"
      << "# and streamed with servoj (lookahead " << num(o.lookahead) << " s, gain " << num(o.gain) << ").\n"
      << "# Needs the Robotiq Grippers URCap (rq_set_force, rq_set_speed, rq_move; registers 0-255) and the\n"
      << "# synchronisation server (tools/export/dashbed_sync.py sync.json) at " << o.sync_host << ":" << o.sync_port
      << ".\n"
      << "def " << function << "():\n"
      << "  dashbed_t = 0.0\n"
      << "  # from plan time t, the cubic Hermite piece from (t0, q0, v0) to (t1, q1, v1) followed until plan\n"
      << "  # time `until`; returns the plan time reached\n"
      << "  def dashbed_follow(t, t0, t1, q0, v0, q1, v1, until):\n"
      << "    h = t1 - t0\n"
      << "    while t < until - 0.0000005:\n"
      << "      s = (t - t0) / h\n"
      << "      a = (2 * s - 3) * s * s + 1\n"
      << "      b = ((s - 2) * s + 1) * s * h\n"
      << "      c = (3 - 2 * s) * s * s\n"
      << "      d = (s - 1) * s * s * h\n"
      << "      q = [a * q0[0] + b * v0[0] + c * q1[0] + d * v1[0], a * q0[1] + b * v0[1] + c * q1[1] + d * v1[1], "
         "a * q0[2] + b * v0[2] + c * q1[2] + d * v1[2], a * q0[3] + b * v0[3] + c * q1[3] + d * v1[3], "
         "a * q0[4] + b * v0[4] + c * q1[4] + d * v1[4], a * q0[5] + b * v0[5] + c * q1[5] + d * v1[5]]\n"
      << "      servoj(q" << servo << "\n"
      << "      t = t + " << num(o.servo_period) << "\n"
      << "    end\n"
      << "    return t\n"
      << "  end\n"
      << "  # from plan time t, standing at q until plan time `until`; returns the plan time reached\n"
      << "  def dashbed_hold(t, q, until):\n"
      << "    while t < until - 0.0000005:\n"
      << "      servoj(q" << servo << "\n"
      << "      t = t + " << num(o.servo_period) << "\n"
      << "    end\n"
      << "    return t\n"
      << "  end\n"
      << "  if not socket_open(\"" << o.sync_host << "\", " << o.sync_port << ", \"" << kSocket << "\"):\n"
      << "    popup(\"" << function << ": no synchronisation server at " << o.sync_host << ":" << o.sync_port
      << "\", \"dashbed\", error=True)\n"
      << "    halt\n"
      << "  end\n"
      << "  rq_activate_and_wait()\n"
      << "  movej(" << list(robot.points.front().q) << ", a=0.5, v=0.5)\n";

  const std::vector<Event> events = eventsOf(robot, function);
  std::size_t next = 0;
  const std::vector<core::TrajectoryPoint>& p = robot.points;
  const auto piece = [&](std::size_t i, double until) {
    out << "  dashbed_t = dashbed_follow(dashbed_t, " << num(p[i].t) << ", " << num(p[i + 1].t) << ", " << list(p[i].q) << ", "
        << list(*p[i].qd) << ", " << list(p[i + 1].q) << ", " << list(*p[i + 1].qd) << ", " << num(until) << ")\n";
  };
  // before the first point, between points, after the last: follow until each event, then it
  while (next < events.size() && events[next].t <= p.front().t) {
    out << "  dashbed_t = dashbed_hold(dashbed_t, " << list(p.front().q) << ", " << num(events[next].t) << ")\n" << events[next].code;
    ++next;
  }
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    while (next < events.size() && events[next].t < p[i + 1].t) {
      piece(i, events[next].t);
      out << events[next].code;
      ++next;
    }
    piece(i, p[i + 1].t);
  }
  for (; next < events.size(); ++next) {
    out << "  dashbed_t = dashbed_hold(dashbed_t, " << list(p.back().q) << ", " << num(events[next].t) << ")\n" << events[next].code;
  }
  out << "  dashbed_t = dashbed_hold(dashbed_t, " << list(p.back().q) << ", " << num(timeline.end) << ")\n"
      << "  stopj(2)\n"
      << "  socket_close(\"" << kSocket << "\")\n"
      << "end\n"
      << function << "()\n";
  return out.str();
}

}  // namespace

std::vector<ExportFile> exportUrScript(const ExportTimeline& timeline, const ExportOptions& options) {
  std::vector<ExportFile> files;
  for (const RobotTimeline& robot : timeline.robots) files.push_back({robot.robot + ".script", program(timeline, robot, options)});
  files.push_back({"sync.json", syncJson(timeline)});
  return files;
}

std::string syncJson(const ExportTimeline& timeline) {
  nlohmann::ordered_json syncs = nlohmann::ordered_json::array();
  for (const SyncPoint& s : timeline.syncs) {
    syncs.push_back({{"index", s.index}, {"t", s.t}, {"robots", s.robots}, {"why", s.why}});
  }
  return syncs.dump(2) + "\n";
}

}  // namespace dashbed::exporting
