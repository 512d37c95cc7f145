#include "raycam/zip_archive.h"

#include <array>
#include <fstream>
#include <limits>
#include <set>
#include <stdexcept>

namespace raycam {

namespace {
// The table of the byte-at-a-time CRC: each byte's remainder after its 8 shifts.
std::array<std::uint32_t, 256> crc_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t byte = 0; byte < 256; ++byte) {
    std::uint32_t c = byte;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    table[byte] = c;
  }
  return table;
}

// Little-endian fields, as every zip header has them.
void put16(std::string& out, std::uint32_t value) {
  out += char(value & 0xFF);
  out += char((value >> 8) & 0xFF);
}
void put32(std::string& out, std::uint32_t value) {
  put16(out, value & 0xFFFF);
  put16(out, value >> 16);
}

constexpr std::uint32_t kLocalHeader = 0x04034b50, kCentralHeader = 0x02014b50, kEnd = 0x06054b50;
constexpr std::uint32_t kVersion = 10;       // 1.0: stored files need nothing later
// Made by a Unix zip (host 3, version 3.0), with rw-r--r-- files: unzip then takes the names as they are
// (from an MS-DOS host it would read them as code page 437: "étape" came out as "+�tape").
constexpr std::uint32_t kMadeBy = (3u << 8) | 30u;
constexpr std::uint32_t kReadWrite = 0100644u << 16;
constexpr std::uint32_t kUtf8Names = 0x0800;  // general purpose bit 11: the names are UTF-8
constexpr std::uint32_t kDosDate = (0u << 9) | (1u << 5) | 1u;  // 1980-01-01, the format's first day: the
                                                                  // same inputs give the same bytes
constexpr std::uint64_t kLimit = std::numeric_limits<std::uint32_t>::max();
}  // namespace

std::uint32_t crc32(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = crc_table();
  std::uint32_t c = 0xFFFFFFFFu;
  for (const char byte : bytes) c = table[(c ^ static_cast<unsigned char>(byte)) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::string zip_stored(const std::vector<ZipEntry>& entries) {
  if (entries.size() > 0xFFFF) throw std::invalid_argument("a zip archive holds at most 65535 files");
  std::set<std::string> names;
  std::string out, central;
  for (const ZipEntry& entry : entries) {
    if (entry.name.empty()) throw std::invalid_argument("a file in a zip archive needs a name");
    if (!names.insert(entry.name).second) throw std::invalid_argument(entry.name + ": twice in one zip archive");
    if (entry.name.size() > 0xFFFF || entry.bytes.size() >= kLimit || out.size() >= kLimit)
      throw std::invalid_argument(entry.name + ": too big for a zip archive (4 GB at most)");
    const std::uint32_t crc = crc32(entry.bytes), size = std::uint32_t(entry.bytes.size());
    const std::uint32_t offset = std::uint32_t(out.size());
    // The fields both headers share, from "version needed" to the name's length.
    std::string common;
    put16(common, kVersion);
    put16(common, kUtf8Names);
    put16(common, 0);  // stored
    put16(common, 0);  // time 00:00
    put16(common, kDosDate);
    put32(common, crc);
    put32(common, size);  // compressed: stored, the same
    put32(common, size);
    put16(common, std::uint32_t(entry.name.size()));
    put16(common, 0);  // no extra field
    put32(out, kLocalHeader);
    out += common + entry.name + entry.bytes;
    put32(central, kCentralHeader);
    put16(central, kMadeBy);
    central += common;
    put16(central, 0);  // no comment
    put16(central, 0);  // disk 0
    put16(central, 0);  // internal attributes
    put32(central, kReadWrite);
    put32(central, offset);
    central += entry.name;
  }
  if (out.size() + central.size() >= kLimit) throw std::invalid_argument("too big for a zip archive (4 GB at most)");
  const std::uint32_t central_at = std::uint32_t(out.size());
  out += central;
  put32(out, kEnd);
  put16(out, 0);  // this disk
  put16(out, 0);  // the central directory's disk
  put16(out, std::uint32_t(entries.size()));
  put16(out, std::uint32_t(entries.size()));
  put32(out, std::uint32_t(central.size()));
  put32(out, central_at);
  put16(out, 0);  // no comment
  return out;
}

void write_zip(const std::string& path, const std::vector<ZipEntry>& entries) {
  const std::string bytes = zip_stored(entries);
  std::ofstream file(path, std::ios::binary);
  if (!file || !file.write(bytes.data(), std::streamsize(bytes.size())) || !file.flush())
    throw std::runtime_error(path + ": cannot write the zip archive");
}

}  // namespace raycam
