#include "tools/stress/stress_page.h"

#include <algorithm>
#include <cstdio>

#include "core/number_text.h"
#include "sim/replay/replay_html.h"

namespace dashbed::tools {
namespace {

using replay::htmlText;

std::string percent(double rate) { return core::fixedText(100.0 * rate, 1) + " %"; }

std::string rateCells(const RateInterval& r) {
  return "<td class=num>" + std::to_string(r.successes) + " / " + std::to_string(r.trials) + "</td><td class=\"num\">" +
         percent(r.rate) + "</td><td class=\"num\">" + percent(r.lower) + " - " + percent(r.upper) + "</td>";
}

/// The success rate against sigma_xy with the intervals as error bars (SVG, 600 x 260).
std::string ratePlot(const std::vector<PointSummary>& points) {
  const double width = 600, height = 260, left = 50, right = 20, top = 15, bottom = 40;
  double largest = 0.0;
  for (const PointSummary& p : points) largest = std::max(largest, p.sigma_xy);
  const double span = largest > 0.0 ? largest * 1.1 : 1.0;
  const auto x = [&](double sigma) { return left + (width - left - right) * (points.size() == 1 ? 0.5 : sigma / span); };
  const auto y = [&](double rate) { return top + (height - top - bottom) * (1.0 - rate); };
  // an attribute, quoted
  const auto at = [](const char* name, double v) { return std::string(" ") + name + "=\"" + core::fixedText(v, 1) + "\""; };
  std::string svg = "<svg id=\"rate-plot\" width=\"600\" height=\"260\" viewBox=\"0 0 600 260\" role=\"img\">";
  svg += "<title>success rate against sigma_xy</title>";
  for (const double rate : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    svg += "<line" + at("x1", left) + at("x2", width - right) + at("y1", y(rate)) + at("y2", y(rate)) +
           " stroke=\"#ddd\"/><text" + at("x", left - 6) + at("y", y(rate) + 4) + " text-anchor=\"end\">" +
           core::fixedText(rate, 2) + "</text>";
  }
  std::string line;
  for (const PointSummary& p : points) {
    const double px = x(p.sigma_xy);
    svg += "<line" + at("x1", px) + at("x2", px) + at("y1", y(p.trials.lower)) + at("y2", y(p.trials.upper)) +
           " stroke=\"#2b6cb0\" stroke-width=\"2\"/>";
    svg += "<circle class=\"point\"" + at("cx", px) + at("cy", y(p.trials.rate)) + " r=\"4\" fill=\"#2b6cb0\"><title>" +
           core::fixedText(p.sigma_xy * 1000.0, 2) + " mm: " + percent(p.trials.rate) + "</title></circle>";
    svg += "<text" + at("x", px) + at("y", height - bottom + 16) + " text-anchor=\"middle\">" +
           core::fixedText(p.sigma_xy * 1000.0, 2) + "</text>";
    if (!line.empty()) line += ' ';
    line.append(core::fixedText(px, 1)).append(",").append(core::fixedText(y(p.trials.rate), 1));
  }
  svg += "<polyline points=\"" + line + "\" fill=\"none\" stroke=\"#2b6cb0\"/>";
  svg += "<text" + at("x", width / 2) + at("y", height - 6) + " text-anchor=\"middle\">sigma_xy [mm]</text>";
  svg += "<text x=\"12\"" + at("y", height / 2) + " transform=\"rotate(-90 12 " + core::fixedText(height / 2, 1) +
         ")\" text-anchor=\"middle\">success rate</text></svg>";
  return svg;
}

}  // namespace

std::string campaignHtml(const CampaignInfo& info, const std::vector<PointSummary>& points,
                         const std::vector<TrialOutcome>& worst, const std::string& trials_folder, bool replays) {
  const CampaignSettings& s = info.settings;
  const bool passed = meetsAll(info, points);
  std::string page =
      "<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8>"
      "<meta http-equiv=Content-Security-Policy content=\"default-src 'none'; style-src 'unsafe-inline'\">"
      "<title>dashbed stress: " + htmlText(info.world) + "</title><style>"
      "body{font:14px/1.45 system-ui,sans-serif;margin:16px 24px;color:#222}"
      "table{border-collapse:collapse;margin:6px 0 18px}td,th{border-bottom:1px solid #ddd;padding:2px 10px;text-align:left}"
      "td.num{text-align:right;font-variant-numeric:tabular-nums}.passed{color:#2e9d4f}.failed{color:#d03a2f}"
      "svg text{font-size:11px;fill:#444}</style></head><body>\n";
  page += "<h1>Stress campaign: " + htmlText(info.world) + "</h1>\n<p>" + htmlText(std::string(toString(s.mode))) +
          " of " + htmlText(info.plan) + ", " + std::to_string(s.trials) + " trials per point, seed " +
          std::to_string(s.seed) + "; sigma_yaw " + core::shortestText(s.sigmas.yaw) + " rad, log mass " +
          core::shortestText(s.sigmas.mass) + ", log friction " + core::shortestText(s.sigmas.friction) + ".";
  if (info.min_success) {
    page += " <b class=" + std::string(passed ? "passed" : "failed") + " id=verdict>" + (passed ? "PASSED" : "FAILED") +
            "</b>: minimum success rate " + percent(*info.min_success) + ".";
  }
  page += "</p>\n<h2>Success rate</h2>\n" + ratePlot(points) + "\n";
  page += "<table id=points><tr><th>sigma_xy [mm]</th><th>trials passed</th><th>rate</th><th>Wilson 95 %</th></tr>";
  for (const PointSummary& p : points) {
    page += "<tr><td class=\"num\">" + core::fixedText(p.sigma_xy * 1000.0, 2) + "</td>" + rateCells(p.trials) + "</tr>";
  }
  page += "</table>\n";
  for (const PointSummary& p : points) {
    page += "<h2>At sigma_xy " + core::fixedText(p.sigma_xy * 1000.0, 2) + " mm</h2>\n";
    page += "<table class=actions><tr><th>action</th><th>passed</th><th>rate</th><th>Wilson 95 %</th></tr>";
    for (const auto& [type, rate] : p.per_type) {
      page += "<tr><td><b>every " + std::string(core::toString(type)) + "</b></td>" + rateCells(rate) + "</tr>";
    }
    for (const auto& [id, rate] : p.per_action) page += "<tr><td>" + htmlText(id) + "</td>" + rateCells(rate) + "</tr>";
    page += "</table>\n<table class=failures><tr><th>failure class</th><th>primary</th><th>occurred in</th></tr>";
    for (int c = 0; c < kFailureClassCount; ++c) {
      page += "<tr><td>" + std::string(toString(static_cast<FailureClass>(c))) + "</td><td class=\"num\">" +
              std::to_string(p.primary[static_cast<std::size_t>(c)]) + "</td><td class=\"num\">" +
              std::to_string(p.any[static_cast<std::size_t>(c)]) + "</td></tr>";
    }
    page += "</table>\n";
  }
  page += "<h2>Worst trials</h2>\n";
  if (worst.empty()) page += "<p>No trial failed.</p>\n";
  page += "<table id=worst><tr><th>trial</th><th>failed actions</th><th>class</th><th>first failure</th></tr>";
  for (const TrialOutcome& o : worst) {
    const std::string folder = (trials_folder.empty() ? "" : trials_folder + "/") + trialDirectoryName(o.index);
    const std::string name = trialDirectoryName(o.index);
    const bool has_replay = replays && !o.actions.empty();
    page += "<tr><td>" + (has_replay ? "<a href=\"" + htmlText(folder) + "/replay.html\">" + name + "</a>" : name) +
            "</td><td class=\"num\">" + std::to_string(o.failedActions()) + "</td><td>" +
            (o.primary ? std::string(toString(*o.primary)) : "-") + "</td><td>" + htmlText(o.failure) + "</td></tr>";
  }
  page += "</table>\n</body></html>\n";
  return page;
}

}  // namespace dashbed::tools
