// A zip archive of a few files, stored as they are (no compression): the page hands several files to the
// browser as one download (a browser asks, or refuses, before a page downloads several), and a figure or a
// case is small text. Any unzip, and every system's file manager, opens it. Written here rather than through
// zlib: the page's Emscripten build has no zlib without a network download.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace raycam {

// The CRC-32 zip and PNG use (IEEE 802.3, reflected polynomial 0xEDB88320): "123456789" -> 0xCBF43926.
std::uint32_t crc32(std::string_view bytes);

struct ZipEntry {
  std::string name;   // the file's name inside the archive (UTF-8, '/' between folders)
  std::string bytes;  // its content
};

// The archive's bytes. Throws std::invalid_argument for an entry without a name, two entries of one name, or
// what the classic format cannot hold (more than 65535 entries, 4 GB or more).
std::string zip_stored(const std::vector<ZipEntry>& entries);

// zip_stored() written to `path`; throws std::runtime_error when the file cannot be written.
void write_zip(const std::string& path, const std::vector<ZipEntry>& entries);

}  // namespace raycam
