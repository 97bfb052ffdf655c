// Reading hot-spot histories from CSV: a header line with column names, the first column the time
// or step, every further column the history (strain or stress) of one named hot spot; one row per
// sample of one duty cycle. Lines starting with '#' and blank lines are skipped. Errors name the
// file, the line and the column and say what was expected (std::invalid_argument).
#ifndef FATIGUE_HISTORY_CSV_H
#define FATIGUE_HISTORY_CSV_H

#include <fatigue/hot_spot_assessment.h>

#include <istream>
#include <string>
#include <vector>

namespace fatigue
{
  struct HistoryTable
  {
    std::string                 source; // file name, for messages
    std::string                 step_column;
    std::vector<double>         steps; // strictly increasing
    std::vector<HotSpotHistory> hot_spots;
  };

  HistoryTable
  read_history_csv(const std::string &path);

  // source_name only labels error messages.
  HistoryTable
  parse_history_csv(std::istream &input, const std::string &source_name);

  // The named hot-spot columns, in the requested order; an unknown name throws listing the columns
  // that exist.
  HistoryTable
  select_columns(const HistoryTable &table, const std::vector<std::string> &names);
} // namespace fatigue

#endif
