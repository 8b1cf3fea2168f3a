#include "dressed_human/core/motion/opensim_motion_file.h"
#include "dressed_human/core/io/text_file.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace dressed_human {
namespace {

// Guards against hostile input (the parser is fuzzed).
constexpr std::size_t kMaxColumns = 100000;

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const std::size_t last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream stream(line);
  for (std::string field; stream >> field;) fields.push_back(field);
  return fields;
}

class MotReader {
 public:
  MotReader(const std::string& text, std::string source) : source_(std::move(source)) {
    std::istringstream stream(text);
    for (std::string line; std::getline(stream, line);) lines_.push_back(line);
  }

  OpenSimTable read() {
    readHeader();
    readLabels();
    readRows();
    return std::move(table_);
  }

 private:
  [[noreturn]] void fail(std::size_t line_index, const std::string& message) const {
    throw OpenSimError(source_ + ":" + std::to_string(line_index + 1) + ": " + message);
  }

  static bool parseWhole(const std::string& text, long long& value) {
    if (text.empty() || text.size() > 18) return false;
    value = 0;
    for (const char c : text) {
      if (c < '0' || c > '9') return false;
      value = value * 10 + (c - '0');
    }
    return true;
  }

  void readHeader() {
    bool degrees_given = false;
    for (; at_ < lines_.size(); ++at_) {
      const std::string line = trim(lines_[at_]);
      if (line == "endheader") {
        ++at_;
        if (!degrees_given) {
          fail(at_ - 1, "the header does not say inDegrees=yes or inDegrees=no: the unit of the angles is unknown");
        }
        return;
      }
      const std::size_t equals = line.find('=');
      if (equals == std::string::npos) {
        if (at_ == 0) table_.name = line;
        continue;  // free text in the header (a description) is allowed
      }
      const std::string key = trim(line.substr(0, equals));
      const std::string value = trim(line.substr(equals + 1));
      long long number = 0;
      if (key == "inDegrees") {
        if (value != "yes" && value != "no") fail(at_, "inDegrees must be 'yes' or 'no', got '" + value + "'");
        table_.in_degrees = value == "yes";
        degrees_given = true;
      } else if (key == "nRows" || key == "datarows") {
        if (!parseWhole(value, number)) fail(at_, key + " must be a whole number, got '" + value + "'");
        declared_rows_ = number;
      } else if (key == "nColumns" || key == "datacolumns") {
        if (!parseWhole(value, number)) fail(at_, key + " must be a whole number, got '" + value + "'");
        declared_columns_ = number;
      }
    }
    fail(lines_.empty() ? 0 : lines_.size() - 1, "no 'endheader' line: this is not an OpenSim .mot/.sto file");
  }

  void readLabels() {
    while (at_ < lines_.size() && trim(lines_[at_]).empty()) ++at_;
    if (at_ >= lines_.size()) fail(lines_.size() - 1, "no column labels after 'endheader'");
    table_.labels = splitFields(lines_[at_]);
    if (table_.labels.size() > kMaxColumns) fail(at_, "more than " + std::to_string(kMaxColumns) + " columns");
    if (table_.labels.empty() || table_.labels[0] != "time") {
      fail(at_, "the first column label must be 'time', got '" + (table_.labels.empty() ? "" : table_.labels[0]) + "'");
    }
    if (table_.labels.size() < 2) fail(at_, "no coordinate columns besides 'time'");
    if (declared_columns_ >= 0 && static_cast<std::size_t>(declared_columns_) != table_.labels.size()) {
      fail(at_, "the header says nColumns=" + std::to_string(declared_columns_) + " but there are " +
                    std::to_string(table_.labels.size()) + " column labels");
    }
    for (std::size_t i = 0; i < table_.labels.size(); ++i) {
      for (std::size_t k = 0; k < i; ++k) {
        if (table_.labels[i] == table_.labels[k]) fail(at_, "column label '" + table_.labels[i] + "' appears twice");
      }
    }
    ++at_;
  }

  void readRows() {
    for (; at_ < lines_.size(); ++at_) {
      const std::vector<std::string> fields = splitFields(lines_[at_]);
      if (fields.empty()) continue;
      if (fields.size() != table_.labels.size()) {
        fail(at_, "row has " + std::to_string(fields.size()) + " values, expected " +
                      std::to_string(table_.labels.size()) + " (one per column label)");
      }
      std::vector<double> row(fields.size());
      for (std::size_t c = 0; c < fields.size(); ++c) {
        char* end = nullptr;
        row[c] = std::strtod(fields[c].c_str(), &end);
        if (end == fields[c].c_str() || *end != '\0') {
          fail(at_, "column '" + table_.labels[c] + "': expected a number, got '" + fields[c] + "'");
        }
        if (!std::isfinite(row[c])) {
          fail(at_, "column '" + table_.labels[c] + "': expected a finite number, got '" + fields[c] + "'");
        }
      }
      if (!table_.times.empty() && !(row[0] > table_.times.back())) {
        fail(at_,
             "time " + fields[0] + " does not increase (previous row: " + std::to_string(table_.times.back()) + ")");
      }
      table_.times.push_back(row[0]);
      table_.rows.push_back(std::move(row));
    }
    if (table_.rows.empty()) fail(lines_.size() - 1, "no data rows");
    if (declared_rows_ >= 0 && static_cast<std::size_t>(declared_rows_) != table_.rows.size()) {
      fail(lines_.size() - 1, "the header says nRows=" + std::to_string(declared_rows_) + " but there are " +
                                  std::to_string(table_.rows.size()) + " data rows");
    }
  }

  std::vector<std::string> lines_;
  std::size_t at_ = 0;
  std::string source_;
  long long declared_rows_ = -1;
  long long declared_columns_ = -1;
  OpenSimTable table_;
};

}  // namespace

int OpenSimTable::findColumn(const std::string& label) const {
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == label) return static_cast<int>(i);
  }
  return -1;
}

std::vector<double> OpenSimTable::column(std::size_t index) const {
  std::vector<double> values;
  values.reserve(rows.size());
  for (const std::vector<double>& row : rows) values.push_back(row.at(index));
  return values;
}

OpenSimTable parseOpenSimMotion(const std::string& text, const std::string& source_name) {
  return MotReader(text, source_name).read();
}

OpenSimTable loadOpenSimMotionFile(const std::string& path) {
  return parseOpenSimMotion(readWholeFileOrThrow<OpenSimError>(path, "the OpenSim motion file"), path);
}

}  // namespace dressed_human
