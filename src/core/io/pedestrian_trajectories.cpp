#include "dressed_human/core/io/pedestrian_trajectories.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "dressed_human/core/io/text_file.h"

namespace dressed_human {
namespace {

constexpr double kObsmatSampleRate = 2.5;  // Hz: the ETH and UCY annotations
// Every whole number below 2^53 is exact in a double; ids and frames beyond are not what they say.
constexpr double kMaxWholeNumber = 9007199254740992.0;
constexpr std::size_t kObsmatColumns = 8;
constexpr std::array<const char*, 5> kJuelichColumnNames = {"id", "frame", "x", "y", "z"};
constexpr std::array<const char*, kObsmatColumns> kObsmatColumnNames = {"frame", "id", "x", "z", "y", "vx", "vz", "vy"};

using Error = PedestrianTrajectoryError;

// Where a row is, turned into "source:line: " only for an error: 60 000 rows need no strings.
struct Location {
  const std::string& source;
  std::size_t line;
  std::string text() const { return source + ":" + std::to_string(line) + ": "; }
};

std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

struct Row {
  std::uint64_t id;
  std::int64_t frame;
  Eigen::Vector3d position;
  std::size_t line;
};

// What the comment lines state, and where (0: not stated).
struct HeaderStatements {
  double frame_rate = 0.0;
  std::size_t frame_rate_line = 0;
  double metres_per_unit = 1.0;
  std::string unit = "m";
  std::size_t unit_line = 0;
};

std::string lowerCase(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view skipBlanks(std::string_view text) {
  while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
  return text;
}

// The blank-separated fields of a row into `fields` (the first fields.size()); returns how many there are.
template <std::size_t N>
std::size_t splitFields(std::string_view line, std::array<std::string_view, N>& fields) {
  std::size_t count = 0;
  for (line = skipBlanks(line); !line.empty(); line = skipBlanks(line)) {
    std::size_t length = 0;
    while (length < line.size() && !isBlank(line[length])) ++length;
    if (count < N) fields[count] = line.substr(0, length);
    ++count;
    line.remove_prefix(length);
  }
  return count;
}

// A number in C notation whatever the locale (from_chars), finite.
double finiteNumber(std::string_view field, const char* column, const Location& where) {
  if (!field.empty() && field.front() == '+')
    field.remove_prefix(1);  // from_chars takes no '+'; printf("%+e") writes it
  double value = 0.0;
  const auto [end, status] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (status == std::errc::result_out_of_range) {
    throw Error(where.text() + "column " + column + " is out of a double's range: '" + std::string(field) + "'");
  }
  if (status != std::errc() || end != field.data() + field.size()) {
    throw Error(where.text() + "column " + column + " is not a number: '" + std::string(field) + "'");
  }
  if (!std::isfinite(value))
    throw Error(where.text() + "column " + column + " is not finite: '" + std::string(field) + "'");
  return value;
}

// Ids and frames: obsmat writes them as floats ("7.8000000e+02"), hence parsed as one.
double wholeNumber(std::string_view field, const char* column, const Location& where) {
  const double value = finiteNumber(field, column, where);
  if (value < 0.0 || value != std::floor(value) || value >= kMaxWholeNumber) {
    throw Error(where.text() + "column " + column + " must be a whole number >= 0, got '" + std::string(field) + "'");
  }
  return value;
}

double metresPer(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "cm") return 0.01;
  if (unit == "mm") return 0.001;
  return 0.0;
}

// The unit of a column label such as "x/cm", "y[m]" or "z(mm)"; empty for any other word.
std::string_view unitOfAxisLabel(std::string_view word) {
  if (word.size() < 3 || (word[0] != 'x' && word[0] != 'y' && word[0] != 'z')) return {};
  std::string_view unit = word.substr(1);
  if (unit.front() == '/') {
    unit.remove_prefix(1);
  } else if ((unit.front() == '[' && unit.back() == ']') || (unit.front() == '(' && unit.back() == ')')) {
    unit = unit.substr(1, unit.size() - 2);
  } else {
    return {};
  }
  return metresPer(unit) > 0.0 ? unit : std::string_view();
}

// PeTrack's column labels ("# id frame x/cm y/cm z/cm") or "# unit: cm".
void readUnitStatement(const std::string& comment, const Location& where, HeaderStatements& header) {
  std::array<std::string_view, 16> words;
  const std::size_t count = std::min(splitFields(comment, words), words.size());
  for (std::size_t i = 0; i < count; ++i) {
    std::string_view unit = unitOfAxisLabel(words[i]);
    if (unit.empty() && (words[i] == "unit:" || words[i] == "units:") && i + 1 < count) {
      unit = words[i + 1];
      if (metresPer(unit) == 0.0)
        throw Error(where.text() + "the unit '" + std::string(unit) + "' is none of m, cm, mm");
    }
    if (unit.empty()) continue;
    if (header.unit_line != 0 && unit != header.unit) {
      throw Error(where.text() + "states the unit " + std::string(unit) + ", line " + std::to_string(header.unit_line) +
                  " stated " + header.unit);
    }
    header.metres_per_unit = metresPer(unit);
    header.unit = std::string(unit);
    header.unit_line = where.line;
  }
}

// "framerate: 25 fps", "framerate: 25.00", "frame rate = 30 Hz".
void readFrameRateStatement(const std::string& comment, const Location& where, HeaderStatements& header) {
  std::size_t key = comment.find("framerate");
  std::size_t key_length = 9;
  if (key == std::string::npos) {
    key = comment.find("frame rate");
    key_length = 10;
  }
  if (key == std::string::npos) return;
  std::string_view rest = skipBlanks(std::string_view(comment).substr(key + key_length));
  if (rest.empty() || (rest.front() != ':' && rest.front() != '=')) return;  // prose about the frame rate
  rest = skipBlanks(rest.substr(1));
  double rate = 0.0;
  const auto [end, status] = std::from_chars(rest.data(), rest.data() + rest.size(), rate);
  if (status != std::errc() || end == rest.data()) {
    throw Error(where.text() + "the frame rate statement holds no number: '#" + comment + "'");
  }
  if (!std::isfinite(rate) || rate <= 0.0) {
    throw Error(where.text() + "the frame rate must be > 0 frames per second, the header states " + shown(rate));
  }
  if (header.frame_rate_line != 0 && rate != header.frame_rate) {
    throw Error(where.text() + "states the frame rate " + shown(rate) + ", line " +
                std::to_string(header.frame_rate_line) + " stated " + shown(header.frame_rate));
  }
  header.frame_rate = rate;
  header.frame_rate_line = where.line;
}

// The format of the first row from its column count, or the given one checked against it.
TrajectoryFormat formatOfFirstRow(std::size_t columns, TrajectoryFormat given, const Location& where) {
  const bool juelich = columns == 4 || columns == 5;
  const bool obsmat = columns == kObsmatColumns;
  const std::string count = std::to_string(columns) + " columns";
  if (given == TrajectoryFormat::kJuelich && !juelich) {
    throw Error(where.text() + count + "; the Jülich format has 4 or 5: id frame x y [z]");
  }
  if (given == TrajectoryFormat::kObsmat && !obsmat) {
    throw Error(where.text() + count + "; the obsmat format has 8: frame id x z y vx vz vy");
  }
  if (given != TrajectoryFormat::kAuto) return given;
  if (juelich) return TrajectoryFormat::kJuelich;
  if (obsmat) return TrajectoryFormat::kObsmat;
  throw Error(where.text() + count +
              ": neither the Jülich format (id frame x y [z], 4 or 5) nor obsmat "
              "(frame id x z y vx vz vy, 8)");
}

Row readRow(const std::array<std::string_view, kObsmatColumns>& fields, std::size_t columns, TrajectoryFormat format,
            const Location& where) {
  Row row{};
  row.line = where.line;
  if (format == TrajectoryFormat::kJuelich) {
    const auto& name = kJuelichColumnNames;
    row.id = static_cast<std::uint64_t>(wholeNumber(fields[0], name[0], where));
    row.frame = static_cast<std::int64_t>(wholeNumber(fields[1], name[1], where));
    row.position.x() = finiteNumber(fields[2], name[2], where);
    row.position.y() = finiteNumber(fields[3], name[3], where);
    row.position.z() = columns == 5 ? finiteNumber(fields[4], name[4], where) : 0.0;
    return row;
  }
  const auto& name = kObsmatColumnNames;
  row.frame = static_cast<std::int64_t>(wholeNumber(fields[0], name[0], where));
  row.id = static_cast<std::uint64_t>(wholeNumber(fields[1], name[1], where));
  row.position = {finiteNumber(fields[2], name[2], where), finiteNumber(fields[4], name[4], where),
                  finiteNumber(fields[3], name[3], where)};
  // The velocities are not read further (the player differentiates the positions), but a row
  // with garbage in them is still a broken row.
  for (std::size_t i = 5; i < kObsmatColumns; ++i) finiteNumber(fields[i], name[i], where);
  return row;
}

struct ParsedText {
  TrajectoryFormat format = TrajectoryFormat::kAuto;
  HeaderStatements header;
  std::vector<Row> rows;
};

ParsedText readLines(std::string_view text, const std::string& source, TrajectoryFormat given) {
  ParsedText parsed;
  std::size_t columns = 0;  // of the first row: every row has as many
  std::size_t first_row_line = 0;
  parsed.rows.reserve(text.size() / 32);
  std::size_t line_number = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view line = skipBlanks(text.substr(begin, end - begin));
    begin = end + 1;
    const Location where{source, ++line_number};
    if (line.empty()) continue;
    if (line.front() == '#') {
      const std::string comment = lowerCase(line.substr(1));
      readFrameRateStatement(comment, where, parsed.header);
      readUnitStatement(comment, where, parsed.header);
      continue;
    }
    std::array<std::string_view, kObsmatColumns> fields;
    const std::size_t count = splitFields(line, fields);
    if (columns == 0) {
      parsed.format = formatOfFirstRow(count, given, where);
      columns = count;
      first_row_line = line_number;
    } else if (count != columns) {
      throw Error(where.text() + std::to_string(count) + " columns, the first row (line " +
                  std::to_string(first_row_line) + ") has " + std::to_string(columns));
    }
    parsed.rows.push_back(readRow(fields, columns, parsed.format, where));
  }
  if (parsed.rows.empty()) {
    throw Error(source + ": no trajectory rows (" + (text.empty() ? "an empty file" : "only comments and blank lines") +
                ")");
  }
  return parsed;
}

// First and last frame and the step of the frame numbers (the greatest common gap of distinct ones).
void frameGrid(const std::vector<Row>& rows, const std::string& source, PedestrianTrajectories& result) {
  std::vector<std::int64_t> frames(rows.size());
  std::transform(rows.begin(), rows.end(), frames.begin(), [](const Row& row) { return row.frame; });
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  std::int64_t step = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) step = std::gcd(step, frames[i] - frames[i - 1]);
  result.first_frame = frames.front();
  result.last_frame = frames.back();
  result.frame_step = std::max<std::int64_t>(step, 1);
  if (result.sampleCount() > kMaxTrajectorySamples) {
    const auto last =
        std::find_if(rows.begin(), rows.end(), [&](const Row& row) { return row.frame == frames.back(); });
    throw Error(Location{source, last->line}.text() + "frame " + std::to_string(frames.back()) + " is " +
                std::to_string(result.sampleCount() - 1) + " samples after the first (frame " +
                std::to_string(frames.front()) + "): more than the " + std::to_string(kMaxTrajectorySamples) +
                " a recording may span (a typo?)");
  }
}

double sampleRate(const ParsedText& parsed, const TrajectoryReadOptions& options, std::int64_t frame_step,
                  const std::string& source) {
  if (parsed.format == TrajectoryFormat::kObsmat)
    return options.frame_rate > 0.0 ? options.frame_rate : kObsmatSampleRate;
  const double frames_per_second = options.frame_rate > 0.0 ? options.frame_rate : parsed.header.frame_rate;
  if (frames_per_second == 0.0) {
    throw Error(source +
                ": the header states no frame rate (a line such as '# framerate: 25 fps'): give the "
                "recording's frames per second (frame_rate)");
  }
  return frames_per_second / static_cast<double>(frame_step);
}

// The rows grouped by person, each by frame; a person twice in one frame is an error.
std::vector<PersonTrajectory> people(std::vector<Row>& rows, const PedestrianTrajectories& grid, double metres_per_unit,
                                     const std::string& source) {
  // Stable: of two rows for one person and frame the earlier line comes first, so that the error
  // names the later one and points back to the first.
  std::stable_sort(rows.begin(), rows.end(),
                   [](const Row& a, const Row& b) { return a.id != b.id ? a.id < b.id : a.frame < b.frame; });
  std::vector<PersonTrajectory> result;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    if (i > 0 && row.id == rows[i - 1].id && row.frame == rows[i - 1].frame) {
      throw Error(Location{source, row.line}.text() + "person " + std::to_string(row.id) + " at frame " +
                  std::to_string(row.frame) + " a second time (first at line " + std::to_string(rows[i - 1].line) +
                  ")");
    }
    if (result.empty() || result.back().id != row.id) result.push_back(PersonTrajectory{row.id, {}});
    TrajectorySample sample;
    sample.step = static_cast<std::size_t>((row.frame - grid.first_frame) / grid.frame_step);
    sample.time = static_cast<double>(sample.step) / grid.sample_rate;
    sample.position = row.position * metres_per_unit;
    result.back().samples.push_back(sample);
  }
  return result;
}

}  // namespace

TrajectoryFormat trajectoryFormatNamed(const std::string& name) {
  if (name == "auto") return TrajectoryFormat::kAuto;
  if (name == "juelich") return TrajectoryFormat::kJuelich;
  if (name == "obsmat") return TrajectoryFormat::kObsmat;
  throw Error("unknown trajectory format '" + name + "': expected auto, juelich or obsmat");
}

const char* trajectoryFormatName(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::kJuelich:
      return "juelich";
    case TrajectoryFormat::kObsmat:
      return "obsmat";
    default:
      return "auto";
  }
}

PedestrianTrajectories parsePedestrianTrajectories(std::string_view text, const std::string& source_name,
                                                   const TrajectoryReadOptions& options) {
  if (!std::isfinite(options.frame_rate) || options.frame_rate < 0.0) {
    throw Error(source_name + ": the given frame rate must be > 0 Hz (or 0: the file's), got " +
                shown(options.frame_rate));
  }
  ParsedText parsed = readLines(text, source_name, options.format);
  PedestrianTrajectories result;
  result.format = parsed.format;
  frameGrid(parsed.rows, source_name, result);
  result.sample_rate = sampleRate(parsed, options, result.frame_step, source_name);
  const double metres_per_unit = parsed.format == TrajectoryFormat::kJuelich ? parsed.header.metres_per_unit : 1.0;
  result.people = people(parsed.rows, result, metres_per_unit, source_name);
  return result;
}

PedestrianTrajectories loadPedestrianTrajectories(const std::string& path, const TrajectoryReadOptions& options) {
  return parsePedestrianTrajectories(readWholeFileOrThrow<Error>(path, "the trajectory file"), path, options);
}

}  // namespace dressed_human
