#include "tools/script/script_parser.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

#include "core/input_text.h"

namespace dashbed::tools {
namespace {

/// Splits the text into statements of whitespace-separated tokens.
std::vector<std::vector<Token>> split(std::string_view script) {
  std::vector<std::vector<Token>> statements(1);
  int line = 1, column = 1;
  std::size_t i = 0;
  const auto endStatement = [&] {
    if (!statements.back().empty()) statements.emplace_back();
  };
  while (i < script.size()) {
    const char c = script[i];
    if (c == '\n') {
      endStatement();
      ++line;
      column = 1;
      ++i;
    } else if (c == ';') {
      endStatement();
      ++column;
      ++i;
    } else if (c == '#') {
      while (i < script.size() && script[i] != '\n') ++i;
    } else if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      ++column;
      ++i;
    } else {
      Token token{"", line, column};
      while (i < script.size() && script[i] != ';' && script[i] != '#' &&
             std::isspace(static_cast<unsigned char>(script[i])) == 0) {
        token.text += script[i];
        ++column;
        ++i;
      }
      statements.back().push_back(std::move(token));
    }
  }
  if (statements.back().empty()) statements.pop_back();
  return statements;
}


/// Reads tokens of one statement in order; `after` is where a missing token is reported.
class Cursor {
 public:
  Cursor(const ScriptParser& parser, const std::vector<Token>& tokens) : parser_(parser), tokens_(tokens) {}
  bool done() const { return next_ == tokens_.size(); }
  const Token* peek() const { return done() ? nullptr : &tokens_[next_]; }
  const Token& take(const std::string& expected) {
    if (done()) parser_.fail(endOfStatement(), "expected " + expected + " after '" + tokens_.back().text + "'");
    return tokens_[next_++];
  }
  void expectWord(const std::string& word) {
    const Token& token = take("'" + word + "'");
    if (token.text != word) parser_.fail(token, "expected '" + word + "', got '" + token.text + "'");
  }
  double number(const std::string& what) {
    const Token& token = take(what);
    double value = 0.0;
    const char* first = token.text.data() + (token.text.starts_with('+') ? 1 : 0);
    const char* last = first + token.text.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || !std::isfinite(value)) {
      parser_.fail(token, "expected " + what + " (a number), got '" + token.text + "'");
    }
    return value;
  }
  Eigen::Vector3d vector3(const std::string& what) {
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = number(what + " (3 numbers)");
    return v;
  }
  void finish() const {
    if (!done()) parser_.fail(tokens_[next_], "unexpected '" + tokens_[next_].text + "' at the end of the statement");
  }
  Token endOfStatement() const {
    const Token& last = tokens_.back();
    return Token{"", last.line, last.column + static_cast<int>(last.text.size()) + 1};
  }

 private:
  const ScriptParser& parser_;
  const std::vector<Token>& tokens_;
  std::size_t next_ = 0;
};


template <typename T, typename Name>
std::string names(const std::vector<T>& items, Name name) {
  std::string list;
  for (const T& item : items) list += (list.empty() ? "" : ", ") + name(item);
  return list.empty() ? "none" : list;
}


/// "offset DX DY DZ" at the end of a pick or place.
void parseOffset(Cursor& cursor, Statement& s) {
  if (const Token* next = cursor.peek(); next != nullptr && next->text == "offset") {
    cursor.take("'offset'");
    s.offset = cursor.vector3("an offset DX DY DZ [m]");
  }
}

}  // namespace

void ScriptParser::fail(const Token& at, const std::string& what) const {
  throw ScriptError(name_ + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": " + what);
}

std::vector<Statement> ScriptParser::parse(std::string_view script) const {
  if (const std::optional<core::TextProblem> problem = core::findTextProblem(script)) {
    throw ScriptError(name_ + ":" + std::to_string(problem->line) + ":" + std::to_string(problem->column) + ": " +
                      problem->what);
  }
  std::vector<Statement> statements;
  for (const std::vector<Token>& tokens : split(script)) statements.push_back(parseStatement(tokens));
  return statements;
}


int ScriptParser::robotIndex(const Token& token) const {
  for (std::size_t r = 0; r < world_.robots.size(); ++r) {
    if (world_.robots[r].name == token.text) return static_cast<int>(r);
  }
  fail(token, "unknown robot '" + token.text + "' (world '" + world_.name + "' has " +
                  names(world_.robots, [](const core::RobotSpec& r) { return r.name; }) + ")");
}

int ScriptParser::objectIndex(const Token& token) const {
  for (std::size_t o = 0; o < world_.objects.size(); ++o) {
    if (world_.objects[o].name == token.text) return static_cast<int>(o);
  }
  fail(token, "unknown object '" + token.text + "' (world '" + world_.name + "' has " +
                  names(world_.objects, [](const core::ObjectSpec& o) { return o.name; }) + ")");
}

int ScriptParser::regionIndex(const Token& token) const {
  for (std::size_t g = 0; g < world_.regions.size(); ++g) {
    if (world_.regions[g].name == token.text) return static_cast<int>(g);
  }
  fail(token, "unknown region '" + token.text + "' (world '" + world_.name + "' has " +
                  names(world_.regions, [](const core::Region& g) { return g.name; }) + ")");
}


Statement ScriptParser::parseStatement(const std::vector<Token>& tokens) const {
  Cursor cursor(*this, tokens);
  Statement s;
  s.robot_token = cursor.take("a robot");
  s.robot = robotIndex(s.robot_token);
  s.verb_token = cursor.take("a verb (picks, places, hands, waits, moves, opens, closes, stays)");
  const std::string& verb = s.verb_token.text;
  if (verb == "picks" || verb == "pick") {
    s.verb = Verb::kPick;
    s.object_token = cursor.take("an object");
    s.object = objectIndex(s.object_token);
    if (const Token* next = cursor.peek(); next != nullptr && next->text == "from") {
      cursor.take("'from'");
      const Token* article = cursor.peek();
      if (article != nullptr && article->text == "the") cursor.take("'the'");
      const Token& where = cursor.take("'side', 'top' or 'above'");
      if (where.text == "side") {
        s.side = true;
      } else if (where.text != "top" && where.text != "above") {
        fail(where, "expected 'side', 'top' or 'above', got '" + where.text + "'");
      }
    }
    parseOffset(cursor, s);
  } else if (verb == "places" || verb == "place") {
    s.verb = Verb::kPlace;
    s.object_token = cursor.take("an object");
    s.object = objectIndex(s.object_token);
    const Token& preposition = cursor.take("'in REGION' or 'at X Y Z'");
    if (preposition.text == "in") {
      s.region = regionIndex(cursor.take("a region"));
    } else if (preposition.text == "at") {
      s.at = cursor.vector3("a position X Y Z [m]");
    } else {
      fail(preposition, "expected 'in REGION' or 'at X Y Z', got '" + preposition.text + "'");
    }
    parseOffset(cursor, s);
  } else if (verb == "hands" || verb == "hand") {
    s.verb = Verb::kHand;
    s.object_token = cursor.take("an object");
    s.object = objectIndex(s.object_token);
    cursor.expectWord("to");
    const Token& receiver = cursor.take("a receiving robot");
    s.receiver = robotIndex(receiver);
    if (s.receiver == s.robot) fail(receiver, s.robot_token.text + " cannot hand an object to itself");
  } else if (verb == "waits" || verb == "wait") {
    s.verb = Verb::kWait;
    const Token* at = cursor.peek();
    s.seconds = cursor.number("a duration [s]");
    if (s.seconds < 0.0) fail(*at, "a wait cannot be negative");
    // a day: longer is a typo, and the plan's millisecond times would overflow
    if (s.seconds > 86400.0) fail(*at, "a wait of at most 86400 s (a day), got " + at->text);
  } else if (verb == "moves" || verb == "move") {
    const Token& where = cursor.take("'home' or 'to Q1 .. Q6'");
    if (where.text == "home") {
      s.verb = Verb::kMoveHome;
    } else if (where.text == "to") {
      s.verb = Verb::kMoveTo;
      for (int j = 0; j < 6; ++j) s.q[j] = cursor.number("six joint angles [rad]");
    } else {
      fail(where, "expected 'home' or 'to Q1 .. Q6', got '" + where.text + "'");
    }
  } else if (verb == "opens" || verb == "open") {
    s.verb = Verb::kOpen;
  } else if (verb == "closes" || verb == "close") {
    s.verb = Verb::kClose;
  } else if (verb == "stays" || verb == "stay") {
    s.verb = Verb::kStay;
  } else {
    fail(s.verb_token, "unknown verb '" + verb + "' (expected picks, places, hands, waits, moves, opens, closes or stays)");
  }
  cursor.finish();
  return s;
}

}  // namespace dashbed::tools
