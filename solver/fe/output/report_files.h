// Writes a run's pictures and report.html into its output directory, each under a temporary name
// renamed when complete (as summary.json), so a reader never sees half a file. Rank 0 only.
#pragma once

#include "output/report_page.h"
#include "output/summary.h"

#include <string>
#include <vector>

namespace compliant
{
  // Replaces `file` with `text` atomically (write file.partial, rename).
  void write_file_atomically(const std::string &file, const std::string &text);

  // The pictures' files, then report.html (which embeds them and shows case_file's text).
  void write_pictures_and_report(const std::string &directory, const RunSummary &summary,
                                 const std::vector<Picture> &pictures, double picture_seconds);
} // namespace compliant
