// gnuplot into a private folder, then each chart moved into place safely (chart_plot.h).
#include <lintel/reference/chart_plot.h>
#include <lintel/file_commit.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace lintel {
namespace {

std::string quoted(const std::string& text) {  // one shell word
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

Status plot_charts(const std::string& dir, const std::string& script, const std::vector<std::string>& charts,
                   std::vector<std::string>& warnings) {
  for (const std::string& name : charts)
    if (std::string why = output_refusal(dir + "/" + name); !why.empty())
      return Status::error(dir + "/" + name + ": " + why);
  std::string temp = dir + "/.charts.XXXXXX";
  std::vector<char> buffer(temp.begin(), temp.end());
  buffer.push_back('\0');
  if (!mkdtemp(buffer.data())) return Status::error(dir + ": cannot make a temporary folder for the charts");
  temp = buffer.data();
  const std::string temp_name = std::filesystem::path(temp).filename().string();  // letters and digits only
  const std::string cmd = "cd " + quoted(dir) + " && gnuplot -e \"outdir='" + temp_name + "/'\" " + quoted(script) +
                          " > " + temp_name + "/gnuplot.log 2>&1";
  const bool plotted = std::system(cmd.c_str()) == 0;
  Status status;
  std::vector<std::string> names = charts;
  names.push_back("gnuplot.log");
  for (const std::string& name : names) {
    const std::string drawn = temp + "/" + name;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(drawn, ec)) continue;
    if (Status s = commit_temporary(drawn, dir + "/" + name); !s && status) status = s;
  }
  std::error_code ec;
  std::filesystem::remove_all(temp, ec);
  if (!plotted)
    warnings.push_back(dir + "/" + script + ": gnuplot failed or is missing (see gnuplot.log); charts skipped");
  return status;
}

}  // namespace lintel
