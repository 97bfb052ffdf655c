#include "app/point_batch.h"

#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  std::vector<BatchPoint> read_batch_points(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("--points: cannot read '" + file + "'");
    std::vector<BatchPoint> points;
    std::string             line;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        if (line.empty())
          continue;
        std::istringstream fields(line);
        BatchPoint         point;
        std::getline(fields, point.output_directory, '\t');
        for (std::string field; std::getline(fields, field, '\t');)
          if (!field.empty())
            {
              if (field.find('=') == std::string::npos)
                throw std::runtime_error("--points: '" + file + "' line " + std::to_string(number) + ": '" + field +
                                         "' is no \"Section/Name=value\"");
              point.overrides.push_back(field);
            }
        if (point.output_directory.empty())
          throw std::runtime_error("--points: '" + file + "' line " + std::to_string(number) +
                                   ": no output directory before the first tab");
        points.push_back(point);
      }
    return points;
  }

  int run_batch(const std::string &points_file, const std::vector<BatchPoint> &points,
                const std::function<void(const BatchPoint &)> &run_point, const std::function<bool()> &all_failed,
                MPI_Comm comm)
  {
    const bool    root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    std::ofstream status;
    if (root)
      status.open(points_file + ".status", std::ios::trunc);
    unsigned int failed = 0;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        std::string     message;
        std::error_code ec;
        const bool      existed = std::filesystem::exists(points[k].output_directory, ec);
        try
          {
            run_point(points[k]);
          }
        catch (const std::exception &e)
          {
            message = e.what();
            if (message.empty())
              message = "unknown failure";
          }
        if (!message.empty())
          {
            all_failed(); // returns only when every rank failed alike
            ++failed;
            // Nothing half-written is kept (and nothing that was there before is touched).
            if (root && !existed)
              std::filesystem::remove_all(points[k].output_directory, ec);
          }
        if (root)
          {
            for (auto &c : message)
              if (c == '\n' || c == '\t')
                c = ' ';
            status << k << (message.empty() ? "\tok" : "\tfailed\t" + message) << std::endl;
            if (!message.empty())
              std::cerr << "error: point " << k << ": " << message << std::endl;
          }
      }
    return failed == 0 ? 0 : 3;
  }
} // namespace compliant
