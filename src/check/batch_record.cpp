#include "check/batch_record.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "check/escaped_text.h"

namespace raycam::check {

namespace {
using json = nlohmann::json;

// A folder's name as it is: a string when it is UTF-8 (nearly always), else {"bytes": [...]}. JSON holds no
// other bytes, and the merge computes a student's slice and CSV field from the name read back.
json name_json(const std::string& name) {
  if (valid_utf8(name)) return name;
  json bytes = json::array();
  for (unsigned char byte : name) bytes.push_back(int(byte));
  return json{{"bytes", bytes}};
}

std::string name_of(const json& value) {
  if (value.is_string()) return value.get<std::string>();
  std::string name;
  for (const json& byte : value.at("bytes")) {
    const int b = byte.get<int>();
    if (b < 0 || b > 255) throw json::other_error::create(501, "a byte out of range: " + std::to_string(b), &byte);
    name += char(b);
  }
  return name;
}
}  // namespace

std::string raycam_version() { return RAYCAM_VERSION; }

std::string BatchRecord::difference_from(const BatchRecord& other) const {
  auto differs = [](const std::string& field, const auto& mine, const auto& theirs) {
    return mine == theirs ? std::string() : field + " " + json(mine).dump() + " vs " + json(theirs).dump();
  };
  for (const std::string& difference :
       {differs("raycam", raycam, other.raycam), differs("seed", seed, other.seed), differs("cases", cases, other.cases),
        differs("mode", mode, other.mode), differs("protocol", protocol, other.protocol),
        differs("two_res", two_res, other.two_res), differs("timeout", timeout_seconds, other.timeout_seconds),
        differs("memory", memory_mb, other.memory_mb), differs("disk", disk_mb, other.disk_mb),
        differs("processes", processes, other.processes), differs("student_cmd", student_cmd, other.student_cmd),
        differs("shard count", shard.count, other.shard.count)})
    if (!difference.empty()) return difference;
  return {};
}

std::string battery_sidecar_path(const std::string& csv_path) { return csv_path + ".battery.json"; }

std::string battery_record_json(const BatchRecord& r) {
  json root = {{"raycam", r.raycam},           {"seed", r.seed},
               {"cases", r.cases},             {"mode", r.mode},
               {"protocol", r.protocol},       {"two_res", r.two_res},
               {"timeout", r.timeout_seconds}, {"memory_mb", r.memory_mb},
               {"disk_mb", r.disk_mb},         {"processes", r.processes},
               {"student_cmd", r.student_cmd}, {"shard", shard_text(r.shard)},
               {"students", json::array()}};
  for (const std::string& name : r.students) root["students"].push_back(name_json(name));
  return root.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

BatchRecord read_battery_record(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw std::invalid_argument(path + ": cannot read (each shard's CSV needs the .battery.json that check wrote "
                                       "beside it)");
  BatchRecord r;
  std::string field;
  try {
    const json root = json::parse(in);
    field = "raycam", r.raycam = root.at(field).get<std::string>();
    field = "seed", r.seed = root.at(field).get<unsigned long long>();
    field = "cases", r.cases = root.at(field).get<int>();
    field = "mode", r.mode = root.at(field).get<std::string>();
    // Written before protocols had versions: version 1, which had no --two-res.
    field = "protocol", r.protocol = root.contains(field) ? root.at(field).get<int>() : 1;
    field = "two_res", r.two_res = root.contains(field) ? root.at(field).get<bool>() : false;
    field = "timeout", r.timeout_seconds = root.at(field).get<double>();
    field = "memory_mb", r.memory_mb = root.at(field).get<int>();
    field = "disk_mb", r.disk_mb = root.at(field).get<int>();
    field = "processes", r.processes = root.at(field).get<int>();
    field = "student_cmd", r.student_cmd = root.at(field).get<std::string>();
    field = "students";
    for (const json& name : root.at(field)) r.students.push_back(name_of(name));
    field = "shard", r.shard = parse_shard(root.at(field).get<std::string>(), path + ": shard");
  } catch (const json::exception& error) {
    throw std::invalid_argument(path + ": not a battery record" + (field.empty() ? "" : " (field '" + field + "')") +
                                ": " + error.what());
  }
  return r;
}

}  // namespace raycam::check
