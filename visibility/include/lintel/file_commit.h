// Writing output files so that nothing is half-written and nothing but a regular file is ever
// replaced: every writer of the CLI (scenes, PNGs, benchmark JSON/CSV) goes through here.
// POSIX only (mkstemp, lstat, rename); no dependency beyond the C library.
#pragma once

#include <lintel/status.h>

#include <cstdint>
#include <string>
#include <vector>

namespace lintel {

struct FileContent {
  std::string path;
  const uint8_t* data = nullptr;
  size_t size = 0;
};

// Why `path` may not be written as an output: empty when it does not exist yet or is a regular
// file; otherwise "is a directory", "is a symbolic link to '<target>' (pass that path to write
// there)", "is a character device", "is a FIFO", … Its directory must exist.
std::string output_refusal(const std::string& path);

// Writes every file to a fresh temporary beside it ("<path>.tmp.XXXXXX", made by mkstemp, so an
// existing "<path>.tmp" or any other file is never touched), flushes it to disk, and renames the
// temporaries over their targets only once all were written. Every target is checked with
// output_refusal() first, before anything is created. On failure the temporaries are removed and
// no target changes (a rename failing after an earlier one succeeded leaves that earlier file
// complete). A replaced file keeps its permission bits; a new one gets 0666 less the umask.
// Errors are BadInput with one line naming the path and the fault.
Status commit_files(const std::vector<FileContent>& files);
Status commit_file(const std::string& path, const std::string& text);

// For writers that are separate programs (ffmpeg): a fresh empty temporary beside `path`, with
// `suffix` appended (".mp4" so the program picks the format). The caller fills it, then calls
// commit_temporary() or removes it.
Status make_temporary_beside(const std::string& path, const std::string& suffix, std::string& temporary);
// Checks `path` with output_refusal() again and renames `temporary` over it; removes the
// temporary on failure.
Status commit_temporary(const std::string& temporary, const std::string& path);

}  // namespace lintel
