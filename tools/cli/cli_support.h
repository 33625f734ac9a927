#pragma once
// Shared plumbing of the subcommands: turning exceptions into documented exit codes.

#include <iostream>
#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/asset_paths.h"
#include "core/input_text.h"
#include "core/world_io.h"
#include "tools/cli/commands.h"

namespace dashbed::tools {

/// Runs `f`; bad input (WorldError, runtime_error from files) prints "dashbed WHAT: message"
/// (non-printable bytes escaped)
/// and exits with kExitBadInput; a bad option value (std::invalid_argument) exits with
/// kExitUsage. CLI11 errors (including RuntimeError exit codes) pass through.
template <typename F>
void runGuarded(const char* what, F&& f) {
  try {
    f();
  } catch (const CLI::Error&) {
    throw;
  } catch (const std::runtime_error& e) {
    std::cerr << "dashbed " << what << ": " << core::printableText(e.what()) << "\n";
    throw CLI::RuntimeError(kExitBadInput);
  } catch (const std::invalid_argument& e) {
    std::cerr << "dashbed " << what << ": " << core::printableText(e.what()) << "\n";
    throw CLI::RuntimeError(kExitUsage);
  }
}

/// `json` as the subcommands print it (--json): indented; bytes that are not UTF-8 (in a file
/// or object name) replaced instead of thrown on.
inline std::string jsonText(const nlohmann::json& json) {
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

/// The world file a command was given, or worlds/default.yaml when none.
inline std::filesystem::path worldFileOrDefault(const std::string& file) {
  return file.empty() ? core::defaultWorldPath() : std::filesystem::path(file);
}

}  // namespace dashbed::tools
