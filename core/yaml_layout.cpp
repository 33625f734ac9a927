#include "core/internal/yaml_layout.h"

#include <map>
#include <optional>
#include <sstream>

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

namespace dashbed::core::world_yaml {
namespace {

struct StopScan {};

TextMark markOf(const YAML::Mark& mark) { return {mark.line, mark.column, mark.pos}; }

// Follows the events with a stack of open sequences and maps, so that every node knows its
// path; a node written as a map key gets no path (keys are plain names in world files).
class LayoutHandler : public YAML::EventHandler {
 public:
  LayoutHandler(YamlLayout& layout, std::size_t max_depth) : layout_(layout), max_depth_(max_depth) {}

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (layout_.documents == 1) layout_.second_document = markOf(mark);
  }
  void OnDocumentEnd() override {}
  void OnAnchor(const YAML::Mark&, const std::string& name) override { anchor_name_ = name; }

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, "~"); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string& value) override {
    leaf(mark, anchor, value);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    if (layout_.documents > 0) return;  // aliases are collected in the first document only
    if (const std::optional<std::string> path = nodePath("*")) {
      const auto found = anchors_.find(anchor);
      AliasUse use{*path, markOf(mark), {}, {}};
      if (found != anchors_.end()) {
        use.anchor = found->second.first;
        use.anchor_mark = found->second.second;
      }
      layout_.aliases.push_back(std::move(use));
      valueDone();
    }
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor, false);
  }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor, true);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapEnd() override { close(); }

 private:
  struct Frame {
    bool is_map = false;
    bool is_key = false;  // this container is itself a map key
    std::string path;
    bool expecting_key = true;
    std::string key;
    std::size_t index = 0;
  };

  void remember(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (anchor != YAML::NullAnchor) anchors_[anchor] = {anchor_name_, markOf(mark)};
  }

  // the path of the node starting now; nullopt for a key (whose `text` becomes the key)
  std::optional<std::string> nodePath(const std::string& text) {
    if (frames_.empty()) return std::string();
    Frame& top = frames_.back();
    if (!top.is_map) return top.path + "[" + std::to_string(top.index) + "]";
    if (top.expecting_key) {
      top.key = text;
      top.expecting_key = false;
      return std::nullopt;
    }
    return (top.path.empty() ? "" : top.path + ".") + top.key;
  }

  void valueDone() {
    if (frames_.empty()) return;
    Frame& top = frames_.back();
    if (top.is_map) {
      top.expecting_key = true;
    } else {
      ++top.index;
    }
  }

  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, const std::string& text) {
    remember(mark, anchor);
    if (nodePath(text)) valueDone();
  }

  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool is_map) {
    remember(mark, anchor);
    if (frames_.size() >= max_depth_) {
      layout_.too_deep = true;
      layout_.too_deep_mark = markOf(mark);
      throw StopScan{};
    }
    Frame frame;
    frame.is_map = is_map;
    if (!frames_.empty() && frames_.back().is_map && frames_.back().expecting_key) {
      frame.is_key = true;
    } else {
      frame.path = nodePath("").value_or("");
    }
    frames_.push_back(std::move(frame));
  }

  void close() {
    const bool was_key = frames_.back().is_key;
    frames_.pop_back();
    if (was_key) {
      Frame& parent = frames_.back();
      parent.key.assign(1, '?');  // a key that is a list or map: no field of a world
      parent.expecting_key = false;
    } else {
      valueDone();
    }
  }

 private:
  YamlLayout& layout_;
  std::size_t max_depth_;
  std::vector<Frame> frames_;
  std::map<YAML::anchor_t, std::pair<std::string, TextMark>> anchors_;
  std::string anchor_name_;
};

}  // namespace

YamlLayout scanYamlLayout(std::string_view text, std::size_t max_depth) {
  YamlLayout layout;
  std::istringstream stream{std::string(text)};
  YAML::Parser parser(stream);
  LayoutHandler handler(layout, max_depth);
  try {
    while (layout.documents < 2 && parser.HandleNextDocument(handler)) ++layout.documents;
  } catch (const StopScan&) {
  }
  return layout;
}

const AliasUse* aliasAbove(const YamlLayout& layout, std::string_view path) {
  const AliasUse* best = nullptr;
  for (const AliasUse& use : layout.aliases) {
    const bool contains = path.substr(0, use.path.size()) == use.path &&
                          (path.size() == use.path.size() || path[use.path.size()] == '.' ||
                           path[use.path.size()] == '[');
    if (contains && (best == nullptr || use.path.size() > best->path.size())) best = &use;
  }
  return best;
}

}  // namespace dashbed::core::world_yaml
