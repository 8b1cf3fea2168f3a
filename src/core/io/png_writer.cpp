#include "dressed_human/core/io/png_writer.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dressed_human {
namespace {

const std::array<std::uint32_t, 256>& crcTable() {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> entries{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int bit = 0; bit < 8; ++bit) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      entries[n] = c;
    }
    return entries;
  }();
  return table;
}

void appendBigEndian(std::vector<std::uint8_t>& out, std::uint32_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 24));
  out.push_back(static_cast<std::uint8_t>(value >> 16));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value));
}

void appendChunk(std::vector<std::uint8_t>& file, const char type[4], const std::vector<std::uint8_t>& data) {
  appendBigEndian(file, static_cast<std::uint32_t>(data.size()));
  const std::size_t type_start = file.size();
  file.insert(file.end(), type, type + 4);
  file.insert(file.end(), data.begin(), data.end());
  appendBigEndian(file, crc32OfBytes(file.data() + type_start, file.size() - type_start));
}

// Scanlines (filter byte 0 + raw row) wrapped in a zlib stream of stored deflate blocks.
std::vector<std::uint8_t> zlibStored(const std::vector<std::uint8_t>& raw) {
  std::vector<std::uint8_t> out{0x78, 0x01};
  constexpr std::size_t max_block = 65535;
  std::size_t offset = 0;
  do {
    const std::size_t length = std::min(max_block, raw.size() - offset);
    const bool last = offset + length == raw.size();
    out.push_back(last ? 1 : 0);
    out.push_back(static_cast<std::uint8_t>(length & 0xFF));
    out.push_back(static_cast<std::uint8_t>(length >> 8));
    out.push_back(static_cast<std::uint8_t>(~length & 0xFF));
    out.push_back(static_cast<std::uint8_t>((~length >> 8) & 0xFF));
    out.insert(out.end(), raw.begin() + static_cast<std::ptrdiff_t>(offset),
               raw.begin() + static_cast<std::ptrdiff_t>(offset + length));
    offset += length;
  } while (offset < raw.size());
  appendBigEndian(out, adler32OfBytes(raw.data(), raw.size()));
  return out;
}

void writePngFile(const std::string& path, int width, int height, std::uint8_t bit_depth, std::uint8_t colour_type,
                  const std::vector<std::uint8_t>& scanlines) {
  std::vector<std::uint8_t> file{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> header;
  appendBigEndian(header, static_cast<std::uint32_t>(width));
  appendBigEndian(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), {bit_depth, colour_type, 0, 0, 0});
  appendChunk(file, "IHDR", header);
  appendChunk(file, "IDAT", zlibStored(scanlines));
  appendChunk(file, "IEND", {});
  std::ofstream stream(path, std::ios::binary);
  if (!stream) throw std::runtime_error("writePng: cannot open '" + path + "' for writing");
  stream.write(reinterpret_cast<const char*>(file.data()), static_cast<std::streamsize>(file.size()));
  if (!stream) throw std::runtime_error("writePng: failed while writing '" + path + "'");
}

void requireSize(int width, int height, std::size_t samples_per_pixel, std::size_t actual) {
  if (width <= 0 || height <= 0) {
    std::ostringstream message;
    message << "writePng: width and height must be > 0, got " << width << " x " << height;
    throw std::invalid_argument(message.str());
  }
  const std::size_t expected = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * samples_per_pixel;
  if (actual != expected) {
    std::ostringstream message;
    message << "writePng: pixels has " << actual << " samples, expected " << expected;
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

std::uint32_t crc32OfBytes(const std::uint8_t* data, std::size_t size, std::uint32_t crc) {
  const auto& table = crcTable();
  crc = ~crc;
  for (std::size_t at = 0; at < size; ++at) crc = table[(crc ^ data[at]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

std::uint32_t adler32OfBytes(const std::uint8_t* data, std::size_t size) {
  std::uint32_t a = 1, b = 0;
  for (std::size_t at = 0; at < size; ++at) {
    a = (a + data[at]) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

void writePng8(const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels) {
  static const std::uint8_t colour_types[] = {0, 0, 4, 2, 6};
  if (channels < 1 || channels > 4) {
    std::ostringstream message;
    message << "writePng8: channels must be 1..4, got " << channels;
    throw std::invalid_argument(message.str());
  }
  requireSize(width, height, static_cast<std::size_t>(channels), pixels.size());
  const std::size_t row_bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  std::vector<std::uint8_t> scanlines;
  scanlines.reserve((row_bytes + 1) * static_cast<std::size_t>(height));
  for (int row = 0; row < height; ++row) {
    scanlines.push_back(0);
    const auto begin = pixels.begin() + static_cast<std::ptrdiff_t>(row_bytes * static_cast<std::size_t>(row));
    scanlines.insert(scanlines.end(), begin, begin + static_cast<std::ptrdiff_t>(row_bytes));
  }
  writePngFile(path, width, height, 8, colour_types[channels], scanlines);
}

void writePng16Grey(const std::string& path, int width, int height, const std::vector<std::uint16_t>& pixels) {
  requireSize(width, height, 1, pixels.size());
  std::vector<std::uint8_t> scanlines;
  scanlines.reserve((static_cast<std::size_t>(width) * 2 + 1) * static_cast<std::size_t>(height));
  for (int row = 0; row < height; ++row) {
    scanlines.push_back(0);
    for (int column = 0; column < width; ++column) {
      const std::uint16_t value =
          pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)];
      scanlines.push_back(static_cast<std::uint8_t>(value >> 8));
      scanlines.push_back(static_cast<std::uint8_t>(value & 0xFF));
    }
  }
  writePngFile(path, width, height, 16, 0, scanlines);
}

}  // namespace dressed_human
