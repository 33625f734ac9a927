// parseWorldYaml / loadWorldFile: reading and validating version-1 world files.
//
// Reading happens in two passes. The first walks the YAML tree along the format's schema
// and checks each field on its own (type, count, range); it remembers where names and
// references were written. The second checks the world as a whole: unique names, goals
// that name existing things, and start poses that rest on a surface without overlaps.
// Every error is a WorldError "file:line:column: field.path: what is wrong".

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/geometry.h"
#include "core/hande.h"
#include "core/input_text.h"
#include "core/world_io.h"
#include "core/world_yaml_detail.h"
#include "core/internal/yaml_layout.h"

namespace dashbed::core {

namespace {

/// Lists and maps nested deeper than this are refused (a world file nests 5 levels).
constexpr std::size_t kMaxYamlNesting = 64;

YAML::Mark markAt(int line, int column) {
  YAML::Mark mark;
  mark.line = line;
  mark.column = column;
  return mark;
}

using world_yaml::formatNumber;

// geometric tolerances of the start-pose checks [m]
constexpr double kMaxPenetration = 0.001;   // deeper contact than this is an overlap
constexpr double kRestTolerance = 0.002;    // bottom face to surface height
constexpr int kMaxSolverIterations = 1'000'000;
// Bounds that keep a simulation and the planner's slot grids finite: beyond them a value is a
// typo, not a scene (e.g. a region 500 m wide has 30 million slots to try)
constexpr double kMaxLength = 100.0;      // [m] any size
constexpr double kMaxMass = 1000.0;       // [kg]
constexpr double kMinTimeStep = 1e-5;     // [s]
constexpr double kMaxSettleTime = 60.0;   // [s]
constexpr double kMaxGravity = 100.0;     // [m/s^2]

std::string millimetres(double metres) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.1f mm", metres * 1000.0);
  return buffer;
}

// a height for messages, to the tenth of a millimetre
std::string height(double metres) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4f m", metres);
  return buffer;
}

// a YAML value for "got ..." in messages
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return "nothing";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar: {
      std::string text = node.Scalar();
      if (text.size() > 40) text = text.substr(0, 37) + "...";
      return "'" + text + "'";
    }
  }
  return "something else";
}

std::string joinNames(std::initializer_list<std::string_view> names) {
  std::string text;
  for (const std::string_view name : names) {
    if (!text.empty()) text += ", ";
    text += name;
  }
  return text;
}

// one value in the YAML tree with its field path and the mark of its key
struct Field {
  YAML::Node value;
  YAML::Mark key_mark;
  std::string path;

  // where to point at the value; an empty value has no useful mark of its own
  YAML::Mark mark() const {
    const YAML::Mark m = value.Mark();
    return (value.IsNull() || m.is_null()) ? key_mark : m;
  }
  Field item(const YAML::Node& node, std::size_t index) const {
    return {node, node.Mark().is_null() ? mark() : node.Mark(),
            path + "[" + std::to_string(index) + "]"};
  }
};

// where each name was written, to report duplicates with both lines
struct NameUse {
  std::string name;
  std::string path;
  YAML::Mark mark;
};

// references a goal makes, checked once all names are known
struct GoalUse {
  std::string path;
  YAML::Mark mark;
  std::optional<Field> object, object_class;
  Field region;
};

class Reader {
 public:
  /// Reads a file named `file` in messages, whose aliases are in `layout`.
  Reader(std::string file, world_yaml::YamlLayout layout) : file_(std::move(file)), layout_(std::move(layout)) {}

  SourceLocation locate(const YAML::Mark& mark) const {
    if (mark.is_null()) return {file_, 0, 0};
    return {file_, mark.line + 1, mark.column + 1};
  }

  /// Fails at `mark`; a field written through an alias fails at the alias, naming the anchor.
  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& path,
                         const std::string& message) const {
    const std::string field = path.empty() ? "(top level)" : path;
    if (const world_yaml::AliasUse* alias = aliasAbove(path)) {
      const SourceLocation at{file_, alias->mark.line + 1, alias->mark.column + 1};
      throw WorldError(at, field, message + " (the value of alias *" + alias->anchor + ", anchored at line " +
                                      std::to_string(alias->anchor_mark.line + 1) + ")");
    }
    throw WorldError(locate(mark), field, message);
  }
  [[noreturn]] void fail(const Field& field, const std::string& message) const {
    fail(field.mark(), field.path, message);
  }

  World read(const YAML::Node& root);

 private:
  // a map field: its entries by key, checked for duplicate and unknown keys
  class MapView {
   public:
    MapView(const Reader& reader, const Field& field) : reader_(reader), field_(field) {
      if (!field.value.IsMap()) reader.fail(field, "expected a map, got " + describe(field.value));
      for (auto it = field.value.begin(); it != field.value.end(); ++it) {
        // copies: the iterator's pair is a temporary
        const YAML::Node key = it->first;
        const YAML::Node value = it->second;
        if (!key.IsScalar()) {
          reader.fail(key.Mark().is_null() ? field.mark() : key.Mark(), field.path,
                      "keys must be plain names, got " + describe(key));
        }
        const std::string path = (field.path.empty() ? "" : field.path + ".") + key.Scalar();
        entries_.emplace_back(key.Scalar(), Field{value, key.Mark(), path});
      }
      failOnDuplicateKey();
    }

    void allowOnly(std::initializer_list<std::string_view> allowed) const {
      for (const auto& [name, entry] : entries_) {
        if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
          reader_.fail(entry.key_mark, entry.path, "unknown key; allowed: " + joinNames(allowed));
        }
      }
    }

    std::optional<Field> get(std::string_view key) const {
      for (const auto& [name, entry] : entries_) {
        if (name == key) return entry;
      }
      return std::nullopt;
    }

    Field require(std::string_view key, const std::string& why = "required") const {
      if (auto entry = get(key)) return *entry;
      reader_.fail(field_.mark(), childPath(key), "missing (" + why + ")");
    }

    // the first key (in the text's order) written a second time; sorting keeps it linear-logarithmic
    void failOnDuplicateKey() const {
      std::vector<std::size_t> order(entries_.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return entries_[a].first < entries_[b].first; });
      std::optional<std::pair<std::size_t, std::size_t>> duplicate;  // (first, second) entries
      for (std::size_t k = 1; k < order.size(); ++k) {
        if (entries_[order[k]].first != entries_[order[k - 1]].first) continue;
        if (!duplicate || order[k] < duplicate->second) duplicate = {order[k - 1], order[k]};
      }
      if (!duplicate) return;
      const Field& second = entries_[duplicate->second].second;
      reader_.fail(second.key_mark, second.path,
                   "duplicate key (first at line " +
                       std::to_string(entries_[duplicate->first].second.key_mark.line + 1) + ")");
    }

    std::string childPath(std::string_view key) const {
      return (field_.path.empty() ? "" : field_.path + ".") + std::string(key);
    }
    const Field& field() const { return field_; }

   private:
    const Reader& reader_;
    Field field_;
    std::vector<std::pair<std::string, Field>> entries_;
  };

  // scalar values
  double number(const Field& field) const;
  int integer(const Field& field) const;
  std::string text(const Field& field) const;
  std::string identifier(const Field& field) const;
  std::vector<Field> list(const Field& field) const;
  /// A list of at most `most` items.
  std::vector<Field> boundedList(const Field& field, std::size_t most) const {
    std::vector<Field> items = list(field);
    if (items.size() > most) {
      fail(field, "at most " + std::to_string(most) + " entries, not " + std::to_string(items.size()));
    }
    return items;
  }
  std::vector<double> numbers(const Field& field, std::size_t count) const;
  Eigen::Vector3d vector3(const Field& field) const;
  Color color(const Field& field) const;

  // range checks; `what` finishes "must be ..."
  double positive(const Field& field) const;
  /// A positive value at most `most` (in `unit`): sizes, masses, times that a simulation or a
  /// slot grid would otherwise take forever over.
  double positiveAtMost(const Field& field, double most, const std::string& unit) const;
  double nonNegative(const Field& field) const;
  double length(const Field& field) const { return positiveAtMost(field, kMaxLength, " m"); }
  double within(const Field& field, double low, double high, const std::string& unit) const;
  template <std::size_t N>
  std::array<double, N> nonNegativeArray(const Field& field) const;

  // elements
  Pose robotBase(const Field& field) const;
  Pose yawPose(const Field& field, const std::string& owner) const;
  RobotSpec robot(const Field& field);
  FixtureSpec fixture(const Field& field);
  StableSurface surface(const Field& field);
  Region region(const Field& field);
  ObjectSpec object(const Field& field);
  Goal goal(const Field& field);
  void physics(const Field& field, PhysicsSettings& settings) const;
  void controller(const Field& field, ControllerSettings& settings) const;
  void checks(const Field& field, CheckSettings& settings) const;
  void safety(const Field& field, SafetySettings& settings) const;

  std::string name(const MapView& map);

  // whole-world checks
  void checkGoals(const World& world) const;
  void checkStartPoses(const World& world) const;
  void checkRobotBases(const World& world) const;

  const world_yaml::AliasUse* aliasAbove(const std::string& path) const {
    return path.empty() ? nullptr : world_yaml::aliasAbove(layout_, path);
  }

  std::string file_;
  world_yaml::YamlLayout layout_;
  std::vector<NameUse> names_;
  std::unordered_map<std::string, std::size_t> name_index_;  // into names_
  std::vector<GoalUse> goal_uses_;
  std::vector<Field> object_poses_;
  std::vector<Field> robot_bases_;
};

// ---- scalar values ----------------------------------------------------------------------

bool isNonFiniteWord(std::string_view text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  return text == ".inf" || text == ".Inf" || text == ".INF" || text == ".nan" || text == ".NaN" ||
         text == ".NAN";
}

/// Whether a scalar's tag lets it be a number: none (a plain scalar) or YAML's own !!int, and
/// !!float where fractions are allowed. Empty when it does, else what to say about the tag.
std::string numberTagProblem(const YAML::Node& node, bool integer) {
  const std::string yaml_tag = "tag:yaml.org,2002:";
  const std::string& tag = node.Tag();
  if (tag == "?" || tag == yaml_tag + "int" || (!integer && tag == yaml_tag + "float")) return "";
  if (tag == "!") return "the quoted string " + describe(node);
  const std::string shown = tag.rfind(yaml_tag, 0) == 0 ? "!!" + tag.substr(yaml_tag.size()) : tag;
  return describe(node) + " tagged " + shown;
}

double Reader::number(const Field& field) const {
  const YAML::Node& node = field.value;
  if (!node.IsScalar()) fail(field, "expected a number, got " + describe(node));
  const std::string& scalar = node.Scalar();
  if (const std::string problem = numberTagProblem(node, false); !problem.empty()) {
    fail(field, "expected a number, got " + problem);
  }
  if (isNonFiniteWord(scalar)) fail(field, "expected a finite number, got " + describe(node));
  std::string_view digits = scalar;
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (ec == std::errc::result_out_of_range) {
    fail(field, "expected a finite number, got " + describe(node));
  }
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) {
    fail(field, "expected a number, got " + describe(node));
  }
  if (!std::isfinite(value)) fail(field, "expected a finite number, got " + describe(node));
  return value;
}

int Reader::integer(const Field& field) const {
  const YAML::Node& node = field.value;
  if (!node.IsScalar()) fail(field, "expected an integer, got " + describe(node));
  if (const std::string problem = numberTagProblem(node, true); !problem.empty()) {
    fail(field, "expected an integer, got " + problem);
  }
  std::string_view digits = node.Scalar();
  if (!digits.empty() && digits[0] == '+') digits.remove_prefix(1);
  long long value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() ||
      value < -1'000'000'000 || value > 1'000'000'000) {
    fail(field, "expected an integer, got " + describe(node));
  }
  return static_cast<int>(value);
}

std::string Reader::text(const Field& field) const {
  if (!field.value.IsScalar()) fail(field, "expected a string, got " + describe(field.value));
  return field.value.Scalar();
}

std::string Reader::identifier(const Field& field) const {
  std::string value = text(field);
  if (!world_yaml::isIdentifier(value)) {
    fail(field, "expected a name of letters, digits, '_', '-' and '.', got " +
                    describe(field.value));
  }
  return value;
}

std::vector<Field> Reader::list(const Field& field) const {
  if (!field.value.IsSequence()) fail(field, "expected a list, got " + describe(field.value));
  std::vector<Field> items;
  for (auto it = field.value.begin(); it != field.value.end(); ++it) {
    const YAML::Node node = *it;
    items.push_back(field.item(node, items.size()));
  }
  return items;
}

std::vector<double> Reader::numbers(const Field& field, std::size_t count) const {
  const std::string expected = "expected a list of " + std::to_string(count) + " numbers";
  if (!field.value.IsSequence()) fail(field, expected + ", got " + describe(field.value));
  if (field.value.size() != count) {
    fail(field, expected + ", got " + std::to_string(field.value.size()) +
                    (field.value.size() == 1 ? " item" : " items"));
  }
  std::vector<double> values;
  for (const Field& item : list(field)) values.push_back(number(item));
  return values;
}

Eigen::Vector3d Reader::vector3(const Field& field) const {
  const std::vector<double> v = numbers(field, 3);
  return {v[0], v[1], v[2]};
}

Color Reader::color(const Field& field) const {
  if (field.value.IsScalar()) {
    if (const auto named = colorByName(field.value.Scalar())) return *named;
    std::string names;
    for (const auto& named : kNamedColors) {
      names += (names.empty() ? "" : ", ") + std::string(named.name);
    }
    fail(field, "unknown colour " + describe(field.value) + "; use [r, g, b] in [0, 1] or one of " +
                    names);
  }
  if (!field.value.IsSequence()) {
    fail(field, "expected a colour name or [r, g, b], got " + describe(field.value));
  }
  numbers(field, 3);
  const std::vector<Field> items = list(field);
  return {within(items[0], 0.0, 1.0, ""), within(items[1], 0.0, 1.0, ""),
          within(items[2], 0.0, 1.0, "")};
}

double Reader::positive(const Field& field) const {
  const double value = number(field);
  if (!(value > 0.0)) fail(field, "must be > 0, got " + formatNumber(value));
  return value;
}

double Reader::positiveAtMost(const Field& field, double most, const std::string& unit) const {
  const double value = positive(field);
  if (value > most) fail(field, "must be at most " + formatNumber(most) + unit + ", got " + formatNumber(value));
  return value;
}

double Reader::nonNegative(const Field& field) const {
  const double value = number(field);
  if (value < 0.0) fail(field, "must be >= 0, got " + formatNumber(value));
  return value;
}

double Reader::within(const Field& field, double low, double high, const std::string& unit) const {
  const double value = number(field);
  if (value < low || value > high) {
    fail(field, "must be in [" + formatNumber(low) + ", " + formatNumber(high) + "]" + unit +
                    ", got " + formatNumber(value));
  }
  return value;
}

template <std::size_t N>
std::array<double, N> Reader::nonNegativeArray(const Field& field) const {
  numbers(field, N);
  const std::vector<Field> items = list(field);
  std::array<double, N> values{};
  for (std::size_t i = 0; i < N; ++i) values[i] = nonNegative(items[i]);
  return values;
}

// ---- elements -----------------------------------------------------------------------------

std::string Reader::name(const MapView& map) {
  const Field field = map.require("name");
  std::string value = identifier(field);
  const auto [earlier, first] = name_index_.emplace(value, names_.size());
  if (!first) {
    const NameUse& use = names_[earlier->second];
    fail(field, "duplicate name '" + value + "' (also " + use.path + " at line " +
                    std::to_string(use.mark.line + 1) + ")");
  }
  names_.push_back({value, field.path, field.mark()});
  return value;
}

Pose Reader::robotBase(const Field& field) const {
  const MapView map(*this, field);
  map.allowOnly({"xyz", "rpy", "yaw"});
  const Eigen::Vector3d xyz = vector3(map.require("xyz"));
  const auto rpy = map.get("rpy");
  const auto yaw = map.get("yaw");
  if (rpy && yaw) {
    const Field& later = rpy->key_mark.pos > yaw->key_mark.pos ? *rpy : *yaw;
    fail(later.key_mark, field.path, "give either rpy or yaw, not both");
  }
  if (rpy) return makePose(xyz, vector3(*rpy));
  return makePoseXyzYaw(xyz, yaw ? number(*yaw) : 0.0);
}

Pose Reader::yawPose(const Field& field, const std::string& owner) const {
  const MapView map(*this, field);
  if (const auto rpy = map.get("rpy")) {
    fail(rpy->key_mark, rpy->path, owner + " may only turn about z; use yaw instead of rpy");
  }
  map.allowOnly({"xyz", "yaw"});
  const Eigen::Vector3d xyz = vector3(map.require("xyz"));
  const auto yaw = map.get("yaw");
  return makePoseXyzYaw(xyz, yaw ? number(*yaw) : 0.0);
}

RobotSpec Reader::robot(const Field& field) {
  const MapView map(*this, field);
  map.allowOnly({"name", "model", "base", "home"});
  RobotSpec robot;
  robot.where = locate(field.mark());
  robot.name = name(map);
  robot.model = identifier(map.require("model"));
  robot.X_WBase = robotBase(map.require("base"));
  robot_bases_.push_back(map.require("base"));
  robot.home = kDefaultRobotHome;
  if (const auto home = map.get("home")) {
    const std::vector<double> q = numbers(*home, 6);
    std::copy(q.begin(), q.end(), robot.home.begin());
  }
  return robot;
}

FixtureSpec Reader::fixture(const Field& field) {
  const MapView map(*this, field);
  map.allowOnly({"name", "type", "size", "pose", "color", "wall", "levels"});
  FixtureSpec fixture;
  fixture.where = locate(field.mark());
  fixture.name = name(map);

  const Field type = map.require("type");
  const std::string type_name = text(type);
  if (type_name == "box") {
    fixture.type = FixtureType::kBox;
  } else if (type_name == "bin") {
    fixture.type = FixtureType::kBin;
  } else if (type_name == "shelf") {
    fixture.type = FixtureType::kShelf;
  } else {
    fail(type, "unknown fixture type " + describe(type.value) + "; expected box, bin or shelf");
  }

  const Field size = map.require("size");
  numbers(size, 3);
  const std::vector<Field> edges = list(size);
  fixture.size = {length(edges[0]), length(edges[1]), length(edges[2])};
  fixture.X_WF = yawPose(map.require("pose"), "fixtures");
  if (const auto color = map.get("color")) fixture.color = this->color(*color);

  if (const auto wall = map.get("wall")) {
    if (fixture.type == FixtureType::kBox) {
      fail(wall->key_mark, wall->path, "only bins and shelves have walls (this is a box)");
    }
    const double thickness = number(*wall);
    const double limit = 0.5 * std::min(fixture.size.x(), fixture.size.y());
    if (!(thickness > 0.0) || !(thickness < limit)) {
      fail(*wall, "must be > 0 and less than half the smaller horizontal size (" +
                      formatNumber(limit) + " m), got " + formatNumber(thickness));
    }
    if (!(thickness < fixture.size.z())) {
      fail(*wall, "must be less than the height size[2] = " + formatNumber(fixture.size.z()) +
                      " m, got " + formatNumber(thickness));
    }
    fixture.wall_thickness = thickness;
  } else if (fixture.type != FixtureType::kBox) {
    // the default thickness must fit too
    const double limit = 0.5 * std::min(fixture.size.x(), fixture.size.y());
    if (!(fixture.wall_thickness < limit) || !(fixture.wall_thickness < fixture.size.z())) {
      fail(size, "too small for the default wall of " + formatNumber(fixture.wall_thickness) + " m");
    }
  }

  const auto levels = map.get("levels");
  if (fixture.type != FixtureType::kShelf) {
    if (levels) {
      fail(levels->key_mark, levels->path,
           "only shelves have levels (this is a " + type_name + ")");
    }
    return fixture;
  }
  const Field levels_field = levels ? *levels : map.require("levels", "required for shelves");
  const std::vector<Field> items = list(levels_field);
  if (items.empty()) fail(levels_field, "a shelf needs at least one level");
  const double wall = fixture.wall_thickness;
  const double highest = fixture.size.z() - wall;  // top of the board under the top board
  for (const Field& item : items) {
    const double level = number(item);
    if (fixture.levels.empty()) {
      if (level < wall) {
        fail(item, "the lowest board's top must be at least wall = " + formatNumber(wall) +
                       " m above the base, got " + formatNumber(level));
      }
    } else if (!(level >= fixture.levels.back() + wall)) {
      fail(item, "levels must be increasing, each at least wall = " + formatNumber(wall) +
                     " m above the previous; got " + formatNumber(level) + " after " +
                     formatNumber(fixture.levels.back()));
    }
    if (level > highest) {
      fail(item, "must be at most size[2] - wall = " + formatNumber(highest) +
                     " m (below the top board), got " + formatNumber(level));
    }
    fixture.levels.push_back(level);
  }
  return fixture;
}

StableSurface Reader::surface(const Field& field) {
  const MapView map(*this, field);
  map.allowOnly({"name", "center", "size", "yaw"});
  StableSurface surface;
  surface.where = locate(field.mark());
  surface.name = name(map);
  const Eigen::Vector3d center = vector3(map.require("center"));
  const Field size = map.require("size");
  numbers(size, 2);
  const std::vector<Field> edges = list(size);
  surface.size = {length(edges[0]), length(edges[1])};
  const auto yaw = map.get("yaw");
  surface.X_WS = makePoseXyzYaw(center, yaw ? number(*yaw) : 0.0);
  return surface;
}

Region Reader::region(const Field& field) {
  const MapView map(*this, field);
  map.allowOnly({"name", "center", "size", "yaw"});
  Region region;
  region.where = locate(field.mark());
  region.name = name(map);
  const Eigen::Vector3d center = vector3(map.require("center"));
  const Field size = map.require("size");
  numbers(size, 3);
  const std::vector<Field> edges = list(size);
  region.size = {length(edges[0]), length(edges[1]), length(edges[2])};
  const auto yaw = map.get("yaw");
  region.X_WR = makePoseXyzYaw(center, yaw ? number(*yaw) : 0.0);
  return region;
}

ObjectSpec Reader::object(const Field& field) {
  const MapView map(*this, field);
  map.allowOnly({"name", "size", "mass", "friction", "color", "class", "pose"});
  ObjectSpec object;
  object.where = locate(field.mark());
  object.name = name(map);
  if (const auto size = map.get("size")) {
    numbers(*size, 3);
    const std::vector<Field> edges = list(*size);
    object.size = {length(edges[0]), length(edges[1]), length(edges[2])};
  }
  if (const auto mass = map.get("mass")) object.mass = positiveAtMost(*mass, kMaxMass, " kg");
  if (const auto friction = map.get("friction")) object.friction = positive(*friction);
  if (const auto color = map.get("color")) object.color = this->color(*color);
  if (const auto object_class = map.get("class")) object.object_class = identifier(*object_class);
  const Field pose = map.require("pose");
  object.X_WO = yawPose(pose, "objects");
  object_poses_.push_back(pose);
  return object;
}

Goal Reader::goal(const Field& field) {
  const MapView map(*this, field);
  map.allowOnly({"object", "class", "region"});
  Goal goal;
  goal.where = locate(field.mark());
  const auto object = map.get("object");
  const auto object_class = map.get("class");
  if (object && object_class) {
    fail(field, "give either object or class, not both");
  }
  if (!object && !object_class) fail(field, "needs an object or a class");
  if (object) goal.object = identifier(*object);
  if (object_class) goal.object_class = identifier(*object_class);
  const Field region = map.require("region");
  goal.region = identifier(region);
  goal_uses_.push_back({field.path, field.mark(), object, object_class, region});
  return goal;
}

void Reader::physics(const Field& field, PhysicsSettings& settings) const {
  const MapView map(*this, field);
  map.allowOnly({"time_step", "gravity", "solver_iterations", "pad_friction", "fixture_friction",
                 "settle_time"});
  if (const auto f = map.get("time_step")) {
    settings.time_step = within(*f, kMinTimeStep, 0.01, " s");
  }
  if (const auto f = map.get("gravity")) {
    settings.gravity = vector3(*f);
    if (settings.gravity.norm() > kMaxGravity) {
      fail(*f, "must be at most " + formatNumber(kMaxGravity) + " m/s^2 in magnitude, got " +
                   formatNumber(settings.gravity.norm()));
    }
  }
  if (const auto f = map.get("solver_iterations")) {
    settings.solver_iterations = integer(*f);
    if (settings.solver_iterations < 1 || settings.solver_iterations > kMaxSolverIterations) {
      fail(*f, "must be in [1, " + std::to_string(kMaxSolverIterations) + "], got " +
                   std::to_string(settings.solver_iterations));
    }
  }
  if (const auto f = map.get("pad_friction")) settings.pad_friction = positive(*f);
  if (const auto f = map.get("fixture_friction")) settings.fixture_friction = positive(*f);
  if (const auto f = map.get("settle_time")) settings.settle_time = within(*f, 0.0, kMaxSettleTime, " s");
}

void Reader::controller(const Field& field, ControllerSettings& settings) const {
  const MapView map(*this, field);
  map.allowOnly({"kp", "kd", "grip_force", "finger_speed"});
  if (const auto f = map.get("kp")) settings.kp = nonNegativeArray<6>(*f);
  if (const auto f = map.get("kd")) settings.kd = nonNegativeArray<6>(*f);
  if (const auto f = map.get("grip_force")) {
    settings.grip_force = within(*f, kHandeMinForce, kHandeMaxForce, " N (the Robotiq Hand-E range)");
  }
  if (const auto f = map.get("finger_speed")) {
    settings.finger_speed = within(*f, kHandeMinSpeed, kHandeMaxSpeed, " m/s (the Robotiq Hand-E range)");
  }
}

void Reader::checks(const Field& field, CheckSettings& settings) const {
  const MapView map(*this, field);
  map.allowOnly({"slip_tolerance", "slip_angle_tolerance", "lift_clearance", "placement_tolerance",
                 "upright_tolerance", "rest_speed", "settle_time", "tracking_error_limit", "grip_margin",
                 "pad_contact_area"});
  const std::pair<const char*, double*> fields[] = {
      {"slip_tolerance", &settings.slip_tolerance},
      {"slip_angle_tolerance", &settings.slip_angle_tolerance},
      {"lift_clearance", &settings.lift_clearance},
      {"placement_tolerance", &settings.placement_tolerance},
      {"upright_tolerance", &settings.upright_tolerance},
      {"rest_speed", &settings.rest_speed},
      {"settle_time", &settings.settle_time},
      {"tracking_error_limit", &settings.tracking_error_limit},
      {"grip_margin", &settings.grip_margin},
      {"pad_contact_area", &settings.pad_contact_area},
  };
  for (const auto& [key, value] : fields) {
    if (const auto f = map.get(key)) *value = nonNegative(*f);
  }
  if (const auto f = map.get("settle_time")) settings.settle_time = within(*f, 0.0, kMaxSettleTime, " s");
}

void Reader::safety(const Field& field, SafetySettings& settings) const {
  const MapView map(*this, field);
  map.allowOnly({"max_joint_acceleration", "payload", "tcp_speed", "tcp_force", "external_torque"});
  if (const auto f = map.get("max_joint_acceleration")) settings.max_joint_acceleration = positive(*f);
  if (const auto f = map.get("payload")) settings.payload = positive(*f);
  if (const auto f = map.get("tcp_speed")) settings.tcp_speed = positive(*f);
  if (const auto f = map.get("tcp_force")) settings.tcp_force = positive(*f);
  if (const auto f = map.get("external_torque")) settings.external_torque = positive(*f);
}

// ---- the world ----------------------------------------------------------------------------

World Reader::read(const YAML::Node& root) {
  const Field top{root, root.Mark(), ""};
  if (!root.IsMap()) {
    fail(top.mark(), "(top level)",
         "expected a map of world sections starting with 'dashbed_world: " +
             std::to_string(kWorldFormatVersion) + "', got " + describe(root));
  }
  const MapView map(*this, top);

  // the version first: a newer file should say so rather than fail on a new key
  const Field version = map.require("dashbed_world", "a world file starts with 'dashbed_world: " +
                                                         std::to_string(kWorldFormatVersion) + "'");
  const int version_number = integer(version);
  if (version_number != kWorldFormatVersion) {
    fail(version, "unsupported format version " + std::to_string(version_number) +
                      "; this dashbed reads version " + std::to_string(kWorldFormatVersion));
  }
  map.allowOnly({"dashbed_world", "name", "description", "robots", "fixtures", "surfaces",
                 "regions", "objects", "goals", "physics", "controller", "checks", "safety"});

  World world;
  world.name = identifier(map.require("name"));
  if (const auto description = map.get("description")) world.description = text(*description);

  const Field robots = map.require("robots");
  for (const Field& item : list(robots)) world.robots.push_back(robot(item));
  if (world.robots.empty()) fail(robots, "the world needs at least one robot");
  if (world.robots.size() > kMaxRobots) {
    fail(robots, "at most " + std::to_string(kMaxRobots) + " robots, not " + std::to_string(world.robots.size()));
  }

  if (const auto f = map.get("fixtures")) {
    for (const Field& item : boundedList(*f, kMaxFixtures)) world.fixtures.push_back(fixture(item));
  }
  if (const auto f = map.get("surfaces")) {
    for (const Field& item : boundedList(*f, kMaxFixtures)) world.surfaces.push_back(surface(item));
  }
  if (const auto f = map.get("regions")) {
    for (const Field& item : boundedList(*f, kMaxFixtures)) world.regions.push_back(region(item));
  }
  if (const auto f = map.get("objects")) {
    for (const Field& item : list(*f)) world.objects.push_back(object(item));
  }
  if (const auto f = map.get("goals")) {
    for (const Field& item : list(*f)) world.goals.push_back(goal(item));
  }
  if (const auto f = map.get("physics")) physics(*f, world.physics);
  if (const auto f = map.get("controller")) controller(*f, world.controller);
  if (const auto f = map.get("checks")) checks(*f, world.checks);
  if (const auto f = map.get("safety")) safety(*f, world.safety);

  deriveFixtureGeometry(world);
  checkGoals(world);
  checkStartPoses(world);
  checkRobotBases(world);
  return world;
}

void Reader::checkRobotBases(const World& world) const {
  // the base frame is the bottom of the mounting flange: on a fixture's top at most, not inside
  for (std::size_t i = 0; i < world.robots.size(); ++i) {
    const Eigen::Vector3d p_WB = world.robots[i].X_WBase.translation();
    for (const FixtureSpec& fixture : world.fixtures) {
      for (const Box& part : fixture.boxes) {
        if (pointInBox(p_WB, part, -kMaxPenetration)) {
          fail(robot_bases_[i], "robot '" + world.robots[i].name + "' is mounted inside fixture '" + fixture.name +
                                    "' (its base must rest on a fixture's top, not inside it)");
        }
      }
    }
  }
}

void Reader::checkGoals(const World& world) const {
  // indexes by name, so that a world with many objects and goals is checked in linear time
  std::unordered_map<std::string_view, const ObjectSpec*> objects;
  std::unordered_set<std::string_view> classes;
  for (const ObjectSpec& object : world.objects) {
    objects.emplace(object.name, &object);
    classes.insert(object.object_class);
  }
  std::unordered_map<std::string_view, const Region*> regions;
  for (const Region& region : world.regions) regions.emplace(region.name, &region);
  // one goal per object and per class (an object goal may override its class's goal)
  std::unordered_map<std::string_view, std::size_t> object_goals, class_goals;

  for (std::size_t i = 0; i < goal_uses_.size(); ++i) {
    const GoalUse& use = goal_uses_[i];
    const Goal& goal = world.goals[i];
    if (use.object && !objects.contains(goal.object)) {
      fail(*use.object, "unknown object '" + goal.object + "'");
    }
    if (use.object_class && !classes.contains(goal.object_class)) {
      fail(*use.object_class, "no object has class '" + goal.object_class + "'");
    }
    if (!regions.contains(goal.region)) {
      std::string hint;
      if (const FixtureSpec* fixture = world.findFixture(goal.region)) {
        hint = " ('" + goal.region + "' is a " +
               std::string(world_yaml::fixtureTypeName(fixture->type)) +
               " fixture; only bins are regions)";
      } else if (std::any_of(world.surfaces.begin(), world.surfaces.end(),
                             [&](const StableSurface& s) { return s.name == goal.region; })) {
        hint = " ('" + goal.region + "' is a surface; goals need a region)";
      }
      fail(use.region, "unknown region '" + goal.region + "'" + hint);
    }
    const bool by_object = !goal.object.empty();
    auto& goals_by_name = by_object ? object_goals : class_goals;
    const std::string& name = by_object ? goal.object : goal.object_class;
    const auto [earlier, first] = goals_by_name.emplace(name, i);
    if (!first) {
      fail(by_object ? *use.object : *use.object_class,
           std::string(by_object ? "object '" : "class '") + name + "' already has a goal (" +
               goal_uses_[earlier->second].path + " at line " +
               std::to_string(goal_uses_[earlier->second].mark.line + 1) + ")");
    }
  }
  // an object is in its region when its centre is (core::distanceOutside): standing on the
  // region's floor as at its start (upright, yaw only), its centre must be below the top
  for (const ObjectSpec& object : world.objects) {
    std::size_t goal = 0;
    if (const auto by_object = object_goals.find(object.name); by_object != object_goals.end()) {
      goal = by_object->second;
    } else if (const auto by_class = class_goals.find(object.object_class);
               !object.object_class.empty() && by_class != class_goals.end()) {
      goal = by_class->second;
    } else {
      continue;
    }
    const Region& region = *regions.at(world.goals[goal].region);
    if (object.size.z() / 2 <= region.size.z() + 1e-9) continue;
    fail(goal_uses_[goal].region, "object '" + object.name + "' is " + millimetres(object.size.z()) +
                                              " tall: standing in region '" + region.name + "' (" +
                                              millimetres(region.size.z()) +
                                              " high) its centre would be above it, and an object is in a region "
                                              "when its centre is");
  }
}

// The objects' centres in square cells as wide as the widest object: two objects can touch only
// when their cells are the same or neighbours, so each is checked against those alone.
struct ObjectGrid {
  double cell = 0.0;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;

  std::int64_t index(double x) const {
    return static_cast<std::int64_t>(std::clamp(std::floor(x / cell), -2.0e9, 2.0e9));
  }
  static std::uint64_t key(std::int64_t ix, std::int64_t iy) {
    return (static_cast<std::uint64_t>(ix) << 32) ^ static_cast<std::uint64_t>(iy & 0xffffffff);
  }
};

void Reader::checkStartPoses(const World& world) const {
  std::vector<Box> object_boxes;
  object_boxes.reserve(world.objects.size());
  ObjectGrid grid;
  for (const ObjectSpec& object : world.objects) {
    const Box box{object.X_WO, object.size};
    object_boxes.push_back(box);
    const Eigen::Vector3d extent = rotatedBoxExtent(box.X_WB.linear(), box.size);
    grid.cell = std::max({grid.cell, extent.x(), extent.y(), 1e-3});
  }
  std::vector<std::pair<const FixtureSpec*, Box>> fixture_parts;
  for (const FixtureSpec& fixture : world.fixtures) {
    for (const Box& part : fixture.boxes) fixture_parts.emplace_back(&fixture, part);
  }

  for (std::size_t i = 0; i < world.objects.size(); ++i) {
    const ObjectSpec& object = world.objects[i];
    const Field& pose = object_poses_[i];
    const Box& box = object_boxes[i];

    for (const auto& [fixture, part] : fixture_parts) {
      const double depth = boxPenetrationDepth(box, part);
      if (depth > kMaxPenetration) {
        fail(pose, "'" + object.name + "' penetrates fixture '" + fixture->name + "' by " +
                       millimetres(depth) + " (at most " + millimetres(kMaxPenetration) + " allowed)");
      }
    }
    // the earliest object it overlaps, among those in the neighbouring cells
    const std::int64_t ix = grid.index(box.X_WB.translation().x());
    const std::int64_t iy = grid.index(box.X_WB.translation().y());
    std::optional<std::size_t> overlapped;
    double overlap = 0.0;
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto cell = grid.cells.find(ObjectGrid::key(ix + dx, iy + dy));
        if (cell == grid.cells.end()) continue;
        for (const std::size_t j : cell->second) {
          if (overlapped && *overlapped < j) continue;
          const double depth = boxPenetrationDepth(box, object_boxes[j]);
          if (depth > kMaxPenetration) {
            overlapped = j;
            overlap = depth;
          }
        }
      }
    }
    if (overlapped) {
      fail(pose, "'" + object.name + "' overlaps object '" + world.objects[*overlapped].name + "' (line " +
                     std::to_string(object_poses_[*overlapped].mark().line + 1) + ") by " + millimetres(overlap));
    }
    grid.cells[ObjectGrid::key(ix, iy)].push_back(i);

    // resting: bottom face near a surface's height, centre above the surface's rectangle
    const Eigen::Vector3d p_WO = object.X_WO.translation();
    const double bottom = p_WO.z() - 0.5 * object.size.z();
    const StableSurface* nearest = nullptr;
    double nearest_gap = 0.0;
    bool rests = false;
    for (const StableSurface& surface : world.surfaces) {
      const Eigen::Vector3d p_SO = surface.X_WS.inverse(Eigen::Isometry) * p_WO;
      const bool above = std::abs(p_SO.x()) <= 0.5 * surface.size.x() &&
                         std::abs(p_SO.y()) <= 0.5 * surface.size.y();
      if (!above) continue;
      const double gap = bottom - surface.X_WS.translation().z();
      if (std::abs(gap) <= kRestTolerance) {
        rests = true;
        break;
      }
      if (!nearest || std::abs(gap) < std::abs(nearest_gap)) {
        nearest = &surface;
        nearest_gap = gap;
      }
    }
    if (!rests) {
      std::string detail;
      if (nearest) {
        detail = "; the nearest surface under it, '" + nearest->name + "' at z = " +
                 height(nearest->X_WS.translation().z()) + ", is " +
                 millimetres(std::abs(nearest_gap)) + (nearest_gap > 0 ? " below" : " above") +
                 " its bottom face";
      } else {
        detail = "; no stable surface lies under its centre";
      }
      fail(pose, "'" + object.name + "' does not rest on any stable surface (bottom face at z = " +
                     height(bottom) + " must be within " + millimetres(kRestTolerance) +
                     " of a surface under its centre)" + detail);
    }
  }
}

}  // namespace

World parseWorldYaml(std::string_view yaml_text, const std::string& file_name) {
  const Reader reader_for_errors(file_name, {});
  if (const std::optional<TextProblem> problem = findTextProblem(yaml_text)) {
    reader_for_errors.fail(markAt(problem->line - 1, problem->column - 1), "(text)", problem->what);
  }
  // the event scan first: it finds syntax errors, refuses deep nesting before yaml-cpp's tree
  // recurses into it, counts the documents and knows where aliases are used
  world_yaml::YamlLayout layout;
  try {
    layout = world_yaml::scanYamlLayout(yaml_text, kMaxYamlNesting);
  } catch (const YAML::Exception& e) {
    reader_for_errors.fail(e.mark.is_null() ? YAML::Mark() : e.mark, "syntax error", e.msg);
  }
  if (layout.too_deep) {
    reader_for_errors.fail(markAt(layout.too_deep_mark.line, layout.too_deep_mark.column), "(structure)",
                           "nested deeper than " + std::to_string(kMaxYamlNesting) +
                               " levels of lists and maps (a world file needs fewer than 10)");
  }
  if (layout.documents > 1) {
    const world_yaml::TextMark& at = layout.second_document;
    const bool stray_comma = static_cast<std::size_t>(at.offset) < yaml_text.size() && yaml_text[at.offset] == ',';
    reader_for_errors.fail(markAt(at.line, at.column), "(top level)",
                           stray_comma ? "a ',' outside a [list] or {map}"
                                       : "a world file holds one YAML document; found a second one");
  }
  YAML::Node document;
  try {
    document = YAML::Load(std::string(yaml_text));  // the one document the scan found
  } catch (const YAML::Exception& e) {
    reader_for_errors.fail(e.mark.is_null() ? YAML::Mark() : e.mark, "syntax error", e.msg);
  }
  if (document.IsNull()) {
    reader_for_errors.fail(YAML::Mark(), "(top level)",
                           "the file is empty; a world file starts with 'dashbed_world: " +
                               std::to_string(kWorldFormatVersion) + "'");
  }
  try {
    Reader reader(file_name, std::move(layout));
    return reader.read(document);
  } catch (const YAML::Exception& e) {
    // the reader only asks nodes for what they hold; this guards against surprises
    reader_for_errors.fail(e.mark, "(internal)", std::string("YAML error: ") + e.msg);
  }
}

World loadWorldFile(const std::filesystem::path& file) {
  World world = parseWorldYaml(readTextFile<WorldError>(file, "world"), file.string());
  world.source_file = file.string();
  return world;
}

}  // namespace dashbed::core
