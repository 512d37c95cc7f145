// --shard i/N: which students one machine (or one job of an array) grades. A student's slice depends only on
// its folder name and N (a hash of the name, modulo N), never on the other students: a student added later
// lands in a slice of its own, and every other student stays where it was (docs/check.md, "A large course").
#pragma once

#include <cstdint>
#include <string>

namespace raycam::check {

struct Shard {
  int index = 1;  // 1-based, as Slurm's array task ids and GNU parallel's {} count
  int count = 1;
};

// "i/N" with 1 <= i <= N <= 10000; throws std::invalid_argument naming `flag` and the accepted form.
Shard parse_shard(const std::string& text, const std::string& flag);
std::string shard_text(const Shard& shard);  // "i/N"

// FNV-1a, 64 bits, over the name's bytes: a published hash anyone can recompute (in a spreadsheet or a
// script) to see which slice a student is in.
std::uint64_t fnv1a_64(const std::string& bytes);

// The slice (1..count) of the student whose folder is `name`: fnv1a_64(name) mod count, plus 1.
int shard_of(const std::string& name, int count);

}  // namespace raycam::check
