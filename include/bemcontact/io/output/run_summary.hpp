#pragma once
// summary.json: one schema for every problem kind and command (docs/summary.md). Each
// kind fills the blocks it has; the envelope (schema, version, kind, input and its hash,
// the lists) is the same everywhere.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace bemcontact::io {

inline constexpr const char* summary_schema = "bemcontact.summary/1";

struct RunSummary {
  std::string kind;     // "body", "decomposition", "contact", "bodies"
  std::string command;  // "run" or "mesh"
  std::string title;
  std::string analysis;
  std::string input_file;
  std::string_view input_text;  // hashed (SHA-256), not copied
  nlohmann::json parameters = nlohmann::json::object();
  nlohmann::json options = nlohmann::json::object();   // every option, defaults included
  nlohmann::json problem = nlohmann::json::object();   // what the file describes (counts, echo)
  nlohmann::json mesh = nlohmann::json::object();      // nodes, elements, regions {name: {...}}
  nlohmann::json results = nlohmann::json::object();   // kind-specific answers
  nlohmann::json reactions = nlohmann::json::object(); // per region: resultants of its boundaries
  nlohmann::json estimate = nlohmann::json::object();  // unknowns, memory and time foreseen before the run
  nlohmann::json timings = nlohmann::json::object();   // seconds per phase, total
  std::vector<std::string> warnings;
  std::vector<std::string> outputs;                    // the other files of the folder
};

nlohmann::json summary_json(const RunSummary& summary);

// Lower-case hexadecimal SHA-256 of `bytes` (FIPS 180-4).
std::string sha256_hex(std::string_view bytes);

}  // namespace bemcontact::io
