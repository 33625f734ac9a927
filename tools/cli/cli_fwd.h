#pragma once
// CLI11's App, declared for the headers whose functions add options to a command: <CLI/CLI.hpp>
// costs seconds of compile time in every file that includes it, so only the .cpp files that
// define such functions (and the commands) include it.

namespace CLI {
class App;
}  // namespace CLI
