// Minimal PNG writer without zlib: the image data goes into "stored" (uncompressed) deflate
// blocks with our own CRC-32 and Adler-32. Files are larger than compressed PNGs but any viewer
// reads them, and the core keeps no extra link dependency.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dressed_human {

/// 8-bit grey (channels = 1), grey+alpha (2), RGB (3) or RGBA (4), row-major interleaved.
/// Throws std::invalid_argument for a size mismatch, std::runtime_error when the file can't be written.
void writePng8(const std::string& path, int width, int height, int channels, const std::vector<std::uint8_t>& pixels);
/// 16-bit grey.
void writePng16Grey(const std::string& path, int width, int height, const std::vector<std::uint16_t>& pixels);

/// Exposed for tests: CRC-32 (PNG/zlib polynomial) and Adler-32 of a byte range.
std::uint32_t crc32OfBytes(const std::uint8_t* data, std::size_t size, std::uint32_t crc = 0);
std::uint32_t adler32OfBytes(const std::uint8_t* data, std::size_t size);

}  // namespace dressed_human
