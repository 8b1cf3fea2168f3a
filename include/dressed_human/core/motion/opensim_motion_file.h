#pragma once
// OpenSim motion/storage files (.mot, .sto): a header of key=value lines up to "endheader"
// (inDegrees=yes|no says the unit of rotational coordinates), a line of column labels starting
// with "time", then one row of numbers per time.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace dressed_human {

struct OpenSimError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct OpenSimTable {
  std::string name;  // the first header line when it is not key=value
  bool in_degrees = true;
  std::vector<std::string> labels;        // labels[0] == "time"
  std::vector<double> times;              // seconds, strictly increasing
  std::vector<std::vector<double>> rows;  // rows[r][column], column 0 is the time again

  int findColumn(const std::string& label) const;  // -1 when absent
  std::vector<double> column(std::size_t index) const;
};

// Throws OpenSimError "source:line: what": no endheader, no inDegrees, nRows/nColumns that do
// not match the data, non-numeric or non-finite values, times that do not increase, ...
OpenSimTable parseOpenSimMotion(const std::string& text, const std::string& source_name);
OpenSimTable loadOpenSimMotionFile(const std::string& path);

}  // namespace dressed_human
