// The page's several-files download (raycam/zip_archive.h): the CRC against published check values, and the
// archive against Info-ZIP's unzip, which tests every file's CRC and gives back the files as they went in.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "../scratch_dir.h"
#include "raycam/zip_archive.h"

using raycam::ZipEntry;

namespace {
std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}
}  // namespace

TEST_CASE("zip: the CRC-32 gives the published check values", "[io][zip]") {
  // The catalogue of CRC algorithms' check value for CRC-32/ISO-HDLC, and RFC 3720's test of the empty input.
  CHECK(raycam::crc32("123456789") == 0xCBF43926u);
  CHECK(raycam::crc32("") == 0u);
  // "The quick brown fox jumps over the lazy dog": 0x414FA339, the value every CRC-32 reference quotes.
  CHECK(raycam::crc32("The quick brown fox jumps over the lazy dog") == 0x414FA339u);
}

TEST_CASE("zip: unzip -t passes the archive and extracts the files as they went in", "[io][zip]") {
  REQUIRE(std::system("unzip -v >/dev/null 2>&1") == 0);  // Debian's unzip (scripts/install-deps.sh)
  raycam::test::ScratchDir scratch("zip");
  std::string binary;
  for (int i = 0; i < 3000; ++i) binary += char((i * 7919) & 0xFF);  // every byte value, some zeros
  const std::vector<ZipEntry> entries = {{"many3d-figure-a.tex", "\\begin{tikzpicture}\n\\end{tikzpicture}\n"},
                                         {"many3d-figure-b.tex", "second figure\n"},
                                         {"étape-c.bin", binary},
                                         {"empty.txt", ""}};
  const std::string archive = scratch.path("steps.zip");
  raycam::write_zip(archive, entries);
  const std::string log = scratch.path("unzip.log");
  CHECK(std::system(("unzip -t " + archive + " >" + log + " 2>&1").c_str()) == 0);
  INFO(read_all(log));
  CHECK(read_all(log).find("No errors detected") != std::string::npos);
  const std::string out = scratch.path("out");
  REQUIRE(std::system(("unzip -q " + archive + " -d " + out + " >" + log + " 2>&1").c_str()) == 0);
  for (const ZipEntry& entry : entries) {
    INFO(entry.name);
    CHECK(read_all(out + "/" + entry.name) == entry.bytes);
  }
}

TEST_CASE("zip: what the format cannot hold is refused with its reason", "[io][zip]") {
  CHECK_THROWS_AS(raycam::zip_stored({{"", "x"}}), std::invalid_argument);
  CHECK_THROWS_AS(raycam::zip_stored({{"a.tex", "x"}, {"a.tex", "y"}}), std::invalid_argument);
  raycam::test::ScratchDir scratch("zip-refused");
  CHECK_THROWS_AS(raycam::write_zip(scratch.path("no-such-folder/steps.zip"), {{"a", "b"}}), std::runtime_error);
}
