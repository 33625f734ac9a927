#pragma once
// The action-script language: statements of whitespace-separated words ("r0 picks cube_0"),
// separated by ';' or line breaks, '#' starting a comment. Parsing checks the words and the
// names against the world; what the statements mean is planned by planFromScript.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "core/input_text.h"
#include "core/ur_ik.h"
#include "core/world.h"

namespace dashbed::tools {

/// A script that cannot be turned into a plan. The message reads
/// "NAME:LINE:COLUMN: what is wrong", e.g. "script:2:4: unknown verb 'jumps' (...)".
struct ScriptError : core::InputError {
  using core::InputError::InputError;
};

struct Token {
  std::string text;
  int line = 0;
  int column = 0;
};

enum class Verb { kPick, kPlace, kHand, kWait, kMoveHome, kMoveTo, kOpen, kClose, kStay };

struct Statement {
  Verb verb = Verb::kWait;
  Token robot_token;
  Token verb_token;
  int robot = -1;
  Token object_token;  // pick, place, hand
  int object = -1;
  bool side = false;                                  // pick from the side
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();   // pick, place: TCP offset in the object frame [m]
  int region = -1;                                    // place in REGION
  std::optional<Eigen::Vector3d> at;                  // place at X Y Z
  int receiver = -1;                                  // hand
  double seconds = 0.0;                               // wait
  core::ArmConfig q{};                                // move to
};

/// Parses scripts for one world; every error is a ScriptError "NAME:LINE:COLUMN: what".
class ScriptParser {
 public:
  ScriptParser(const core::World& world, std::string name) : world_(world), name_(std::move(name)) {}

  [[noreturn]] void fail(const Token& at, const std::string& what) const;

  /// The statements of `script`, each checked on its own (names exist, numbers are numbers).
  std::vector<Statement> parse(std::string_view script) const;

 private:
  Statement parseStatement(const std::vector<Token>& tokens) const;
  int robotIndex(const Token& token) const;
  int objectIndex(const Token& token) const;
  int regionIndex(const Token& token) const;

  const core::World& world_;
  std::string name_;
};

}  // namespace dashbed::tools
