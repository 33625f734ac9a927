#include "planner/scheduling/robot_conflicts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

namespace dashbed::planner {
namespace {

constexpr Millis kGridStep = 20;          // [ms] extra check times between key times
constexpr double kFarApart = 2.6;         // [m] bases farther apart than twice the reach + tool: never touch
constexpr double kClearanceSlack = 1e-4;  // [m] a robot check skipped by clearance keeps this in hand
constexpr double kCheckWindow = 1.0;      // [s] robot pairs are checked side by side this much at a time

/// Two boxes (min, max corners), each grown by its own distance, do not overlap.
bool boxesApart(const std::pair<Eigen::Vector3d, Eigen::Vector3d>& a, double grow_a,
                const std::pair<Eigen::Vector3d, Eigen::Vector3d>& b, double grow_b) {
  const double grow = grow_a + grow_b;
  return ((a.first.array() - grow > b.second.array()) || (b.first.array() - grow > a.second.array())).any();
}

/// Whether an interval of robot pair `pair` ending at t1 [s] is known free: before `from`, or
/// where `known` (may be null) says so (true for all t1 up to some time, false after it).
struct KnownFree {
  double from = 0.0;
  const PairKnowledge* known = nullptr;
  std::size_t pair = 0;
  bool operator()(double t1) const {
    return t1 <= from || (known != nullptr && t1 <= known->checked[pair] && t1 < known->same[pair]);
  }
};

/// One robot pair's part of firstConflictPairs: the intervals between its check times (every
/// point time of both robots and a regular grid), checked in order from the first one not known
/// free, as far as the caller asks at a time.
class PairCheck {
 public:
  PairCheck(const ScheduleView& view, const Schedule& schedule, const CollisionScene& scene, CollisionChecker& checker,
            int a, int b, KnownFree known_free)
      : view_(&view), schedule_(&schedule), scene_(&scene), checker_(&checker), a_(a), b_(b), known_free_(known_free) {
    if (known_free_(toSeconds(schedule.makespan))) {
      start_ = schedule.makespan;
      return;
    }
    // the grid starts at its last regular time up to which all is known free: the intervals
    // before it end by then
    Millis lo = 0, hi = schedule.makespan / kGridStep;  // known free up to lo's time (t1 = 0 is)
    while (lo < hi) {
      const Millis mid = lo + (hi - lo + 1) / 2;
      if (known_free_(toSeconds(mid * kGridStep))) {
        lo = mid;
      } else {
        hi = mid - 1;
      }
    }
    const Millis begin = lo * kGridStep;
    // the two robots' point times from there on (a robot's segments run one after another);
    // the regular grid's times come in as the intervals are walked
    std::array<std::vector<Millis>, 2> lists;
    for (const int r : {a, b}) {
      std::vector<Millis>& times = lists[r == a ? 0 : 1];
      const Timeline& line = view.timeline(r);
      for (std::size_t k = 0; k < line.segments.size(); ++k) {
        for (const Millis t : line.times[k]) {
          if (schedule.start[line.segments[k]] + t > begin) times.push_back(schedule.start[line.segments[k]] + t);
        }
      }
      if (!std::is_sorted(times.begin(), times.end())) std::sort(times.begin(), times.end());
    }
    points_.reserve(lists[0].size() + lists[1].size());
    std::merge(lists[0].begin(), lists[0].end(), lists[1].begin(), lists[1].end(), std::back_inserter(points_));
    start_ = begin;
  }

  /// Checks the next intervals that start before `until` and no later than `latest` [s]. The
  /// pair's first conflict when one of them has it (the pair is then done).
  std::optional<RobotConflict> advance(double until, double latest) {
    for (; !done(); start_ = nextTime()) {
      const double t0 = toSeconds(start_);
      if (t0 >= until) return std::nullopt;
      if (t0 > latest) {
        checked_ = t0;
        break;
      }
      if (std::optional<RobotConflict> conflict = check(t0, toSeconds(nextTime()))) {
        checked_ = t0;
        start_ = schedule_->makespan;
        return conflict;
      }
    }
    start_ = schedule_->makespan;
    return std::nullopt;
  }

  bool done() const { return start_ >= schedule_->makespan; }
  /// [s] The start of the first interval not found free (when not done: the next one).
  double checkedUntil() const { return done() ? checked_ : toSeconds(start_); }

 private:
  /// The check time after start_: the next point time of either robot or of the grid.
  Millis nextTime() {
    while (point_ < points_.size() && points_[point_] <= start_) ++point_;
    const Millis grid = (start_ / kGridStep + 1) * kGridStep;
    return std::min({grid, schedule_->makespan, point_ < points_.size() ? points_[point_] : grid});
  }

  /// The first colliding sample in [t0, t1], or none.
  std::optional<RobotConflict> check(double t0, double t1) {
    if (known_free_(t1)) return std::nullopt;
    const ScheduleView& view = *view_;
    const Schedule& schedule = *schedule_;
    const CollisionScene& scene = *scene_;
    const int a = a_, b = b_;
    const RobotState a0 = view.at(a, t0, true), b0 = view.at(b, t0, true);
    // a handoff's two robots were checked against each other when it was sampled
    const auto in_step = [&](int r, const RobotState& s) {
      const Timeline& line = view.timeline(r);
      return s.item >= 0 && schedule.segments[line.segments[s.item]].motion != nullptr
                 ? schedule.segments[line.segments[s.item]].step
                 : -2;
    };
    if (in_step(a, a0) >= 0 && in_step(a, a0) == in_step(b, b0)) return std::nullopt;
    const RobotState a1 = view.at(a, t1, false), b1 = view.at(b, t1, false);
    const bool still = sameState(a0, a1) && sameState(b0, b1);
    if (still && standing_ && sameState(a0, standing_->first) && sameState(b0, standing_->second)) return std::nullopt;
    const Eigen::VectorXd qa0 = view.full(a, a0), qb0 = view.full(b, b0);
    if (withinMeasured(a0, qa0, a1, b0, qb0, b1)) {
      standing_ = still ? std::optional(std::pair{a0, b0}) : std::nullopt;
      return std::nullopt;
    }
    const int steps_a = scene.motionSteps(a, qa0, view.full(a, a1), a0.held);
    const int steps_b = scene.motionSteps(b, qb0, view.full(b, b1), b0.held);
    // no point moves farther than its steps' motion_step within the interval: robots whose
    // bounding boxes at its start stay apart by that much are free throughout
    // (the gap between the boxes is a clearance as well: the robots' points stay inside)
    const auto bounds_a = checker_->robotBounds(a, qa0, a0.held), bounds_b = checker_->robotBounds(b, qb0, b0.held);
    const double step = scene.settings().motion_step;
    if (boxesApart(bounds_a, steps_a * step, bounds_b, steps_b * step)) {
      measured_ = {qa0, qb0, a0.held, b0.held, boxesGap(bounds_a, bounds_b)};
      standing_ = still ? std::optional(std::pair{a0, b0}) : std::nullopt;
      return std::nullopt;
    }
    // evenly in time, so that no point moves more than motion_step between samples where
    // the robot moves fastest within the interval
    const int steps = static_cast<int>(std::ceil(std::max(view.peakOverMeanSpeed(a, a0.item, t0, t1) * steps_a,
                                                          view.peakOverMeanSpeed(b, b0.item, t0, t1) * steps_b) -
                                                 1e-9));
    // the interval's own fingers and held objects, also at its end
    const auto state_at = [&](int r, int k, const RobotState& s0, const RobotState& s1) {
      const RobotState s = k == 0 ? s0 : k == steps ? s1 : view.at(r, t0 + (t1 - t0) * k / steps, true);
      return view.full(r, {s.q, s0.finger, s0.held, 0});
    };
    // Samples are checked in order; after a free one, the samples up to which the robots'
    // points together travel less than their clearance there are free as well (each joint
    // moves monotonically within the interval), and are skipped.
    Eigen::VectorXd qa = state_at(a, 0, a0, a1), qb = state_at(b, 0, b0, b1);
    for (int k = 0; k <= steps;) {
      const double t = t0 + (t1 - t0) * k / steps;
      const double clearance = checker_->robotsClearance(a, qa, a0.held, b, qb, b0.held);
      if (clearance < 0.0) return RobotConflict{t, a, b, a0.item, b0.item};
      measured_ = {qa, qb, a0.held, b0.held, clearance};
      // The next sample checked is the first the robots may reach within the clearance.
      // Their travel from sample k grows with the samples after it (each joint moves
      // monotonically), so it is found by doubling the stride, then halving it.
      Eigen::VectorXd reach_a, reach_b;  // the states at the first sample found to reach
      const auto reaches = [&](int n) {
        Eigen::VectorXd na = state_at(a, n, a0, a1), nb = state_at(b, n, b0, b1);
        const double travel = scene.motionTravel(a, qa, na, a0.held) + scene.motionTravel(b, qb, nb, b0.held);
        if (travel + kClearanceSlack < clearance) return false;
        reach_a = std::move(na);
        reach_b = std::move(nb);
        return true;
      };
      int short_of = k, next = k + 1;  // short_of: not reaching (or k); next: the candidate
      while (next <= steps && !reaches(next)) {
        short_of = next;
        next = k + 2 * (next - k);
      }
      if (next > steps) next = short_of < steps && reaches(steps) ? steps : steps + 1;
      while (next <= steps && next - short_of > 1) {
        const int mid = short_of + (next - short_of) / 2;
        (reaches(mid) ? next : short_of) = mid;
      }
      k = next;
      qa = std::move(reach_a);
      qb = std::move(reach_b);
    }
    standing_ = still ? std::optional(std::pair{a0, b0}) : std::nullopt;
    return std::nullopt;
  }

  /// The interval's pieces lie within the clearance of measured_ (the travel from a point is a
  /// weighted sum of |dq|: along a move's straight piece it is largest at one of the piece's
  /// ends; along a transition's cubic, whose joints each move monotonically, at the corner of
  /// the box between the ends farthest from the point). q0: the interval's start configurations.
  bool withinMeasured(const RobotState& a0, const Eigen::VectorXd& qa0, const RobotState& a1, const RobotState& b0,
                      const Eigen::VectorXd& qb0, const RobotState& b1) const {
    if (measured_.clearance <= 0.0 || !sameHeld(measured_.held_a, a0.held) || !sameHeld(measured_.held_b, b0.held)) {
      return false;
    }
    const CollisionScene& scene = *scene_;
    const auto travel = [&](int r, const Eigen::VectorXd& q, const RobotState& s0, const Eigen::VectorXd& q0,
                            const RobotState& s1) {
      const Eigen::VectorXd q1 = view_->full(r, {s1.q, s0.finger, s0.held, 0});
      if (!view_->onCurve(r, s0.item)) {
        return std::max(scene.motionTravel(r, q, q0, s0.held), scene.motionTravel(r, q, q1, s0.held));
      }
      const Eigen::VectorXd corner = ((q - q0).cwiseAbs().array() >= (q - q1).cwiseAbs().array()).select(q0, q1);
      return scene.motionTravel(r, q, corner, s0.held);
    };
    return travel(a_, measured_.qa, a0, qa0, a1) + travel(b_, measured_.qb, b0, qb0, b1) + kClearanceSlack <
           measured_.clearance;
  }

  const ScheduleView* view_;
  const Schedule* schedule_;
  const CollisionScene* scene_;
  CollisionChecker* checker_;
  int a_, b_;
  KnownFree known_free_;
  std::vector<Millis> points_;  ///< both robots' point times after the first check time, sorted
  std::size_t point_ = 0;       ///< the first of points_ after start_ (or before)
  Millis start_ = 0;            ///< the next interval's start
  double checked_ = std::numeric_limits<double>::infinity();
  /// both robots standing as they stood in the last interval checked: nothing new to check
  std::optional<std::pair<RobotState, RobotState>> standing_;
  /// the last sample whose clearance was measured: robots that together travel less than it
  /// from there (holding the same) are free
  struct Measured {
    Eigen::VectorXd qa, qb;
    std::optional<HeldObject> held_a, held_b;
    double clearance = -1.0;
  } measured_;
};

}  // namespace

std::optional<RobotConflict> firstConflictPairs(const MotionHypergraph& graph, const ScheduleView& view,
                                                const Schedule& schedule, double from, const PairKnowledge* known,
                                                std::vector<double>* checked) {
  CollisionChecker checker(graph.scene());
  const std::size_t robots = graph.world().world->robots.size();
  std::vector<PairCheck> pairs;
  std::vector<std::size_t> index;  // of each pair: a * robots + b
  for (std::size_t ra = 0; ra < robots; ++ra) {
    for (std::size_t rb = ra + 1; rb < robots; ++rb) {
      const auto& spec_a = graph.world().world->robots[ra];
      const auto& spec_b = graph.world().world->robots[rb];
      if ((spec_a.X_WBase.translation() - spec_b.X_WBase.translation()).norm() > kFarApart) continue;
      const std::size_t pair = ra * robots + rb;
      pairs.emplace_back(view, schedule, graph.scene(), checker, static_cast<int>(ra), static_cast<int>(rb),
                         KnownFree{from, known, pair});
      index.push_back(pair);
    }
  }
  std::optional<RobotConflict> first;
  std::size_t first_pair = 0;
  for (double until = from + kCheckWindow;; until += kCheckWindow) {
    bool open = false;
    for (std::size_t p = 0; p < pairs.size(); ++p) {
      if (pairs[p].done()) continue;
      const std::optional<RobotConflict> conflict =
          pairs[p].advance(until, first ? first->t : std::numeric_limits<double>::infinity());
      if (conflict && (!first || conflict->t < first->t || (conflict->t == first->t && p < first_pair))) {
        first = conflict;
        first_pair = p;
      }
      open = open || !pairs[p].done();
    }
    if (!open || (first && until > first->t)) break;
  }
  if (checked != nullptr) {
    checked->assign(robots * robots, std::numeric_limits<double>::infinity());
    for (std::size_t p = 0; p < pairs.size(); ++p) (*checked)[index[p]] = pairs[p].checkedUntil();
  }
  return first;
}

std::optional<RobotConflict> firstConflict(const MotionHypergraph& graph, const Schedule& schedule, double from) {
  return firstConflictPairs(graph, ScheduleView(graph, schedule), schedule, from, nullptr, nullptr);
}

}  // namespace dashbed::planner
