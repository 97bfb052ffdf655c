#include "output/report_files.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  void write_file_atomically(const std::string &file, const std::string &text)
  {
    const std::string partial = file + ".partial";
    {
      std::ofstream out(partial, std::ios::binary);
      out << text;
      if (!out)
        throw std::runtime_error("cannot write '" + partial + "'");
    }
    if (std::rename(partial.c_str(), file.c_str()) != 0)
      throw std::runtime_error("cannot rename '" + partial + "' to '" + file + "'");
  }

  void write_pictures_and_report(const std::string &directory, const RunSummary &summary,
                                 const std::vector<Picture> &pictures, const double picture_seconds)
  {
    const auto start = std::chrono::steady_clock::now();
    for (const auto &p : pictures)
      write_file_atomically(directory + "/" + p.file, p.svg);
    std::ifstream      in(summary.case_file);
    std::ostringstream case_text;
    case_text << in.rdbuf();
    const double seconds =
      picture_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_file_atomically(directory + "/report.html", report_html(summary, case_text.str(), pictures, seconds));
  }
} // namespace compliant
