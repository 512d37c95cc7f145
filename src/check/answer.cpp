#include "answer.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace raycam::check {

namespace {
using json = nlohmann::json;

struct BadAnswer {
  std::string message;
};

int integer_id(const json& value, const std::string& where) {
  if (value.is_number_integer() || value.is_number_unsigned()) {
    const long long id = value.get<long long>();
    if (id < -(1LL << 31) || id > (1LL << 31) - 1) throw BadAnswer{where + ": " + value.dump() + " is not an id"};
    return int(id);
  }
  if (value.is_number_float()) {
    const double id = value.get<double>();
    if (std::isfinite(id) && id == std::floor(id) && std::abs(id) < 2e9) return int(id);
  }
  throw BadAnswer{where + ": expected an integer id, got " + value.dump().substr(0, 40)};
}

std::vector<int> id_row(const json& row, const std::string& where) {
  if (!row.is_array()) throw BadAnswer{where + ": expected a list of integers"};
  std::vector<int> ids;
  ids.reserve(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) ids.push_back(integer_id(row[i], where + "[" + std::to_string(i) + "]"));
  return ids;
}

std::vector<double> matrix(const json& md, int side) {
  const std::string expected = "md: expected " + std::to_string(side) + " rows of " + std::to_string(side) + " numbers";
  if (!md.is_array() || int(md.size()) != side) throw BadAnswer{expected};
  std::vector<double> values;
  for (const json& row : md) {
    if (!row.is_array() || int(row.size()) != side) throw BadAnswer{expected};
    for (const json& value : row) {
      if (!value.is_number() || !std::isfinite(value.get<double>())) throw BadAnswer{expected + " (finite)"};
      values.push_back(value.get<double>());
    }
  }
  return values;
}
}  // namespace

ParsedAnswer parse_answer(const std::string& text, int dimension, int rows, int columns, int objects) {
  ParsedAnswer parsed;
  try {
    json root;
    try {
      root = json::parse(text);
    } catch (const json::parse_error& error) {
      throw BadAnswer{std::string("not JSON: ") + error.what()};
    }
    if (!root.is_object() || !root.contains("ids")) throw BadAnswer{"expected a JSON object with \"ids\""};
    Answer answer;
    const json& ids = root["ids"];
    if (dimension == 2) {
      answer.ids = id_row(ids, "ids");
      answer.columns = int(answer.ids.size());
    } else {
      if (!ids.is_array()) throw BadAnswer{"ids: expected a list of rows"};
      answer.rows = int(ids.size());
      for (std::size_t r = 0; r < ids.size(); ++r) {
        std::vector<int> row = id_row(ids[r], "ids[" + std::to_string(r) + "]");
        if (r == 0) answer.columns = int(row.size());
        if (int(row.size()) != answer.columns)
          throw BadAnswer{"ids[" + std::to_string(r) + "]: " + std::to_string(row.size()) +
                          " columns where row 0 has " + std::to_string(answer.columns)};
        answer.ids.insert(answer.ids.end(), row.begin(), row.end());
      }
    }
    for (std::size_t i = 0; i < answer.ids.size(); ++i)
      if (answer.ids[i] < -1 || answer.ids[i] >= objects) {
        const std::string at = dimension == 2 ? "ids[" + std::to_string(i) + "]"
                                              : "ids[" + std::to_string(i / std::size_t(std::max(answer.columns, 1))) +
                                                    "][" + std::to_string(i % std::size_t(std::max(answer.columns, 1))) + "]";
        throw BadAnswer{at + " = " + std::to_string(answer.ids[i]) + ": expected an id in [-1, " +
                        std::to_string(objects - 1) + "]"};
      }
    if (root.contains("md") && !root["md"].is_null()) answer.md = matrix(root["md"], dimension + 1);
    parsed.answer = answer;
    if (answer.rows != rows || answer.columns != columns) {
      parsed.wrong_size = true;
      parsed.error = dimension == 2 ? "expected " + std::to_string(columns) + " ids, got " + std::to_string(answer.columns)
                                    : "expected " + std::to_string(rows) + " rows of " + std::to_string(columns) +
                                          " ids, got " + std::to_string(answer.rows) + " of " +
                                          std::to_string(answer.columns);
    }
  } catch (const BadAnswer& bad) {
    parsed.answer.reset();
    parsed.error = bad.message;
  }
  return parsed;
}

std::string answer_to_json(const Answer& answer, int dimension) {
  json root;
  if (dimension == 2) {
    root["ids"] = answer.ids;
  } else {
    json rows = json::array();
    for (int r = 0; r < answer.rows; ++r)
      rows.push_back(std::vector<int>(answer.ids.begin() + std::ptrdiff_t(r) * answer.columns,
                                      answer.ids.begin() + std::ptrdiff_t(r + 1) * answer.columns));
    root["ids"] = rows;
  }
  if (answer.md) {
    const int side = dimension + 1;
    json md = json::array();
    for (int r = 0; r < side; ++r)
      md.push_back(std::vector<double>(answer.md->begin() + r * side, answer.md->begin() + (r + 1) * side));
    root["md"] = md;
  }
  return root.dump() + "\n";
}

}  // namespace raycam::check
