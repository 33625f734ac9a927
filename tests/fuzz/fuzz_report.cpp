// Report files: read or refused with a ReportError; a report that is read writes back to
// text that reads to the same bytes.
#include <cstdlib>

#include "fuzz_input.h"
#include "sim/report.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dashbed;
  fuzz::expectReadOrRefuse<sim::ReportError>([&] {
    const sim::Report report = sim::readReportJson(fuzz::textOf(data, size), "fuzz.json");
    const std::string text = sim::writeReportJson(report);
    if (sim::writeReportJson(sim::readReportJson(text, "written.json")) != text) std::abort();
    sim::writeJUnitXml(report);
  });
  return 0;
}
