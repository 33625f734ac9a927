#include "tools/bench/bench_record.h"

#include <chrono>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "tools/bench/bench_table.h"

namespace dashbed::tools {
namespace {

/// The value after "key" and a colon or '=' on the first line of `file` that starts with it.
std::string field(const char* file, const std::string& key, char separator) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) != 0) continue;
    const std::size_t at = line.find(separator);
    if (at == std::string::npos) continue;
    std::string value = line.substr(at + 1);
    value.erase(0, value.find_first_not_of(" \t\""));
    value.erase(value.find_last_not_of(" \t\"") + 1);
    return value;
  }
  return "";
}

std::string readFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

}  // namespace

MachineInfo thisMachine() {
  MachineInfo machine;
  machine.cpu = field("/proc/cpuinfo", "model name", ':');
  machine.cores = static_cast<int>(std::thread::hardware_concurrency());
  const std::string kib = field("/proc/meminfo", "MemTotal", ':');
  if (!kib.empty()) machine.memory_gib = std::stod(kib) / (1024.0 * 1024.0);
  machine.os = field("/etc/os-release", "PRETTY_NAME", '=');
  return machine;
}

void recordSection(const std::filesystem::path& file, const std::string& name, const std::string& title,
                   const std::string& command, const std::string& body) {
  const MachineInfo machine = thisMachine();
  std::ostringstream section;
  section << "<!-- bench:" << name << " -->\n## " << title << "\n\n"
          << "Measured " << utcNow() << " by dashbed " << DASHBED_VERSION << " on "
          << (machine.cpu.empty() ? "an unknown CPU" : machine.cpu) << ", " << machine.cores << " logical cores, "
          << fixed(machine.memory_gib, 0) << " GiB" << (machine.os.empty() ? "" : ", " + machine.os) << ":\n\n"
          << "```sh\n" << command << "\n```\n\n" << body << (body.empty() || body.back() == '\n' ? "" : "\n")
          << "<!-- /bench:" << name << " -->";
  std::string text = readFile(file);
  const std::string begin = "<!-- bench:" + name + " -->", end = "<!-- /bench:" + name + " -->";
  const std::size_t a = text.find(begin);
  const std::size_t b = a == std::string::npos ? std::string::npos : text.find(end, a);
  if (a != std::string::npos && b != std::string::npos) {
    text.replace(a, b + end.size() - a, section.str());
  } else {
    if (!text.empty()) text.append(text.back() == '\n' ? "\n" : "\n\n");
    text.append(section.str()).append("\n");
  }
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace dashbed::tools
