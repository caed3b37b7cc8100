// Charts drawn by gnuplot without letting gnuplot write over anything: it draws into a private
// folder (mkdtemp) and every chart is then moved into place by commit_temporary (file_commit.h),
// so a symlink, device or FIFO named like a chart is refused, as for every other output.
#pragma once

#include <lintel/status.h>

#include <string>
#include <vector>

namespace lintel {

// The first line of every chart script: `outdir` is where `set output outdir.'<name>'` writes;
// empty when a user reruns the script by hand in its folder.
inline constexpr const char* kChartScriptPrologue = "if (!exists(\"outdir\")) outdir = ''\n";

// Runs `gnuplot <script>` in `dir` (the script and its data files are already there) and moves
// `charts` (file names the script writes through `outdir`) and gnuplot.log into `dir`.
// gnuplot missing or failing is a warning (the data files stay), not an error; an output that
// may not be replaced is an error.
Status plot_charts(const std::string& dir, const std::string& script, const std::vector<std::string>& charts,
                   std::vector<std::string>& warnings);

}  // namespace lintel
