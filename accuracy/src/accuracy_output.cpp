// CSV, JSON and gnuplot charts of an accuracy benchmark run (accuracy_bench.h). The charts are
// drawn by an external gnuplot process from .dat files written beside them, so the data behind
// every chart stays inspectable.
#include <lintel/reference/accuracy_bench.h>
#include <lintel/reference/chart_plot.h>
#include <lintel/file_commit.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

namespace lintel {
namespace {

std::string label_of(const MethodScore& s) { return s.settings.empty() ? s.method : s.method + " " + s.settings; }

bool has_false_negatives(const MethodScore& s) { return s.cell_false_negatives + s.instance_false_negatives > 0; }

void csv_row(std::ostream& f, const MethodScore& s) {
  f << s.scene << ',' << s.method << ',' << s.settings << ',' << (s.claims_conservative ? 1 : 0) << ',' << s.cells
    << ',' << s.instances << ',' << s.views << ',' << s.cell_false_negatives << ',' << s.instance_false_negatives << ','
    << s.cell_false_negatives_few_rays << ',' << s.instance_false_negatives_few_rays << ','
    << s.views_with_false_negatives << ',' << s.cell_past_rim_culled << ',' << s.instance_past_rim_culled << ','
    << s.rim_ray_fraction() << ',' << s.over_inclusion() << ',' << s.median_over_inclusion() << ','
    << s.cell_over_inclusion() << ',' << s.area_ratio() << ',' << (s.views ? double(s.pops) / s.views : 0.0) << ','
    << s.max_pops << ',' << s.bound_hits << ',' << s.max_bounds_drift << ',' << median_ms(s.times_ms) << ','
    << percentile_ms(s.times_ms, 0.99) << '\n';
}

void json_row(std::ostream& f, const MethodScore& s, bool last) {
  f << "    {\"scene\": \"" << s.scene << "\", \"method\": \"" << s.method << "\", \"settings\": \"" << s.settings
    << "\", \"claims_conservative\": " << (s.claims_conservative ? "true" : "false") << ", \"cells\": " << s.cells
    << ", \"instances\": " << s.instances << ", \"views\": " << s.views
    << ", \"cell_false_negatives\": " << s.cell_false_negatives
    << ", \"instance_false_negatives\": " << s.instance_false_negatives
    << ", \"cell_false_negatives_few_rays\": " << s.cell_false_negatives_few_rays
    << ", \"instance_false_negatives_few_rays\": " << s.instance_false_negatives_few_rays
    << ", \"views_with_false_negatives\": " << s.views_with_false_negatives
    << ", \"cell_past_rim_culled\": " << s.cell_past_rim_culled
    << ", \"instance_past_rim_culled\": " << s.instance_past_rim_culled
    << ", \"rim_ray_fraction\": " << s.rim_ray_fraction() << ", \"over_inclusion\": " << s.over_inclusion()
    << ", \"median_over_inclusion\": " << s.median_over_inclusion()
    << ", \"ideal_box_over_inclusion\": " << s.ideal_box_over_inclusion()
    << ", \"cell_over_inclusion\": " << s.cell_over_inclusion() << ", \"area_ratio_vs_exact\": " << s.area_ratio()
    << ", \"mean_pops\": " << (s.views ? double(s.pops) / s.views : 0.0) << ", \"max_pops\": " << s.max_pops
    << ", \"bound_hits\": " << s.bound_hits << ", \"max_bounds_drift\": " << s.max_bounds_drift
    << ", \"median_ms\": " << median_ms(s.times_ms) << ", \"p99_ms\": " << percentile_ms(s.times_ms, 0.99)
    << ", \"false_negative_examples\": [";
  for (size_t i = 0; i < s.false_negative_examples.size(); ++i)
    f << (i ? ", " : "") << '"' << s.false_negative_examples[i] << '"';
  f << "]}" << (last ? "\n" : ",\n");
}

// The setting of each method drawn in the scene-size chart: Lintel's defaults for polygon, the
// first setting listed for the others.
bool primary_setting(const MethodScore& s, std::map<std::string, std::string>& chosen) {
  auto it = chosen.find(s.method);
  if (it == chosen.end()) {
    const bool poly = s.method == "polygon";
    if (poly && s.settings != "lattice=1024 cap=16") return false;
    chosen[s.method] = s.settings;
    return true;
  }
  return it->second == s.settings;
}

}  // namespace

Status write_accuracy_outputs(const AccuracyBenchResult& result, const std::string& dir,
                              std::vector<std::string>& warnings) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return Status::error(dir + ": cannot create the output folder (" + ec.message() + ")");
  const std::vector<MethodScore> merged = merge_scores(result.scores);
  // Every file is built in memory and committed at the end (file_commit.h): nothing half-written,
  // nothing but a regular file replaced.
  std::ostringstream csv_file, json_file, ok_file, bad_file, size_file, gp_file;
  {
    std::ostringstream& f = csv_file;
    f << "scene,method,settings,claims_conservative,cells,instances,views,cell_false_negatives,"
         "instance_false_negatives,cell_false_negatives_few_rays,instance_false_negatives_few_rays,"
         "views_with_false_negatives,cell_past_rim_culled,instance_past_rim_culled,rim_ray_fraction,"
         "over_inclusion,median_over_inclusion,cell_over_inclusion,"
         "area_ratio_vs_exact,mean_pops,max_pops,bound_hits,max_bounds_drift,median_ms,p99_ms\n";
    for (const MethodScore& s : result.scores) csv_row(f, s);
    for (const MethodScore& s : merged) csv_row(f, s);
  }
  {
    std::ostringstream& f = json_file;
    f << "{\n  \"wall_s\": " << result.wall_s << ",\n  \"all\": [\n";
    for (size_t i = 0; i < merged.size(); ++i) json_row(f, merged[i], i + 1 == merged.size());
    f << "  ],\n  \"per_scene\": [\n";
    for (size_t i = 0; i < result.scores.size(); ++i) json_row(f, result.scores[i], i + 1 == result.scores.size());
    f << "  ]\n}\n";
  }
  bool any_false_negatives = false, any_clean = false;  // an empty series is left out (gnuplot fails on it)
  // Chart data: one line per method setting (all scenes), one block per method (by scene size).
  {
    std::ostringstream &ok = ok_file, &bad = bad_file;
    // Column 4 places the label: settings of one method sit on top of each other, so the labels
    // of the i-th setting of a method are raised by 1.3^i (one text line on the log axis).
    std::map<std::string, int> seen;
    for (const MethodScore& s : merged) {
      (has_false_negatives(s) ? any_false_negatives : any_clean) = true;
      const double ms = median_ms(s.times_ms);
      (has_false_negatives(s) ? bad : ok) << s.over_inclusion() << ' ' << ms << " \"" << label_of(s) << "\" "
                                          << ms * std::pow(1.3, seen[s.method]++) << "\n";
    }
  }
  std::map<std::string, std::string> chosen;
  std::map<std::string, std::vector<std::pair<uint32_t, double>>> by_method;
  for (const MethodScore& s : result.scores)
    if (primary_setting(s, chosen)) by_method[label_of(s)].emplace_back(s.cells, median_ms(s.times_ms));
  std::ostringstream size_plot;
  {
    std::ostringstream& f = size_file;
    size_t block = 0;
    for (auto& [label, points] : by_method) {
      std::sort(points.begin(), points.end());
      f << "# " << label << "\n";
      for (const auto& [cells, ms] : points) f << cells << ' ' << ms << '\n';
      f << "\n\n";
      size_plot << (block ? ", " : "") << "'time_vs_scene_size.dat' index " << block << " with linespoints title '"
                << label << "'";
      ++block;
    }
  }
  {
    std::ostringstream& f = gp_file;
    f << kChartScriptPrologue;
    for (const char* term : {"pngcairo size 1100,700", "svg size 1100,700"}) {
      const std::string ext = std::string(term).rfind("png", 0) == 0 ? "png" : "svg";
      f << "set terminal " << term << "\nset grid\nset logscale y\nset key outside right\n";
      f << "set logscale x\nset output outdir.'speed_vs_accuracy." << ext << "'\n"
        << "set title 'Time per frame against over-inclusion (all scenes; red crosses: false negatives)'\n"
        << "set xlabel 'over-inclusion (drawn / truly visible instances, log)'\nset ylabel 'median ms per frame'\n"
        << "plot ";
      if (any_clean)
        f << "'speed_vs_accuracy_ok.dat' using 1:2 with points pt 7 ps 1.2 title 'no false negatives', "
             "'' using 1:4:3 with labels offset 0.8,0 left font ',8' notitle";
      if (any_false_negatives)
        f << (any_clean ? ", " : "")
          << "'speed_vs_accuracy_fn.dat' using 1:2 with points pt 2 ps 2 lc rgb 'red' title 'false negatives', "
             "'' using 1:4:3 with labels offset 0.8,0 left font ',8' tc rgb 'red' notitle";
      f << "\n";
      f << "set output outdir.'time_vs_scene_size." << ext << "'\n"
        << "set title 'Time per frame against scene size (median over views)'\n"
        << "set xlabel 'cells'\nset ylabel 'median ms per frame'\nplot " << size_plot.str() << "\nunset logscale x\n";
    }
  }
  const std::string files[][2] = {{"accuracy.csv", csv_file.str()},
                                  {"accuracy.json", json_file.str()},
                                  {"speed_vs_accuracy_ok.dat", ok_file.str()},
                                  {"speed_vs_accuracy_fn.dat", bad_file.str()},
                                  {"time_vs_scene_size.dat", size_file.str()},
                                  {"charts.gp", gp_file.str()}};
  std::vector<FileContent> contents;
  for (const auto& [name, text] : files)
    contents.push_back({dir + "/" + name, reinterpret_cast<const uint8_t*>(text.data()), text.size()});
  if (Status s = commit_files(contents); !s) return s;
  return plot_charts(
      dir, "charts.gp",
      {"speed_vs_accuracy.png", "speed_vs_accuracy.svg", "time_vs_scene_size.png", "time_vs_scene_size.svg"}, warnings);
}

}  // namespace lintel
