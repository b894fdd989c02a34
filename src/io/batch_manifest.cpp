#include "io/batch_manifest.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "io/csv_field.hpp"
#include "io/json_string.hpp"
#include "molsurf/atoms.hpp"
#include "molsurf/error.hpp"

namespace molsurf::io {

namespace {

bool is_structure_file(const std::filesystem::path& path) {
  try {
    structure_format_from_path(path);
    return true;
  } catch (const Error&) {
    return false;
  }
}

std::string trimmed(const std::string& line) {
  const auto first = line.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
}

std::string json_string(const std::string& s) {
  std::string out;
  append_json_string(out, s);
  return out;
}

// The shortest decimal that reads back to the same double.
std::string number(double x) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
}

}  // namespace

std::vector<std::filesystem::path> batch_inputs(const std::filesystem::path& list_or_directory) {
  namespace fs = std::filesystem;
  std::vector<fs::path> inputs;
  std::error_code error;
  if (fs::is_directory(list_or_directory, error)) {
    for (fs::recursive_directory_iterator it(list_or_directory, fs::directory_options::skip_permission_denied, error),
         end;
         !error && it != end; it.increment(error))
      if (it->is_regular_file(error) && is_structure_file(it->path())) inputs.push_back(it->path());
    if (error) throw Error(list_or_directory.string() + ": cannot list: " + error.message());
    std::sort(inputs.begin(), inputs.end());
  } else {
    std::ifstream list(list_or_directory);
    if (!list) throw Error(list_or_directory.string() + ": cannot read the list of structures");
    const fs::path base = list_or_directory.parent_path();
    std::size_t line_number = 0;
    for (std::string line; std::getline(list, line);) {
      ++line_number;
      line = trimmed(line.substr(0, line.find('#')));
      if (line.empty()) continue;
      const fs::path path = fs::path(line).is_absolute() ? fs::path(line) : base / line;
      if (!is_structure_file(path))
        throw Error(list_or_directory.string() + ":" + std::to_string(line_number) + ": '" + line +
                    "' is not a structure file (.pdb .ent .cif .mmcif, optionally .gz, .pqr .xyzr)");
      inputs.push_back(path);
    }
  }
  if (inputs.empty()) throw Error(list_or_directory.string() + ": no structure files to run");
  return inputs;
}

std::vector<std::string> batch_result_names(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::string> names;
  std::map<std::string, int> seen;
  for (const std::filesystem::path& p : inputs) {
    std::filesystem::path stem = p.filename();
    while (stem.has_extension()) stem = stem.stem();
    const int n = ++seen[stem.string()];
    names.push_back(n == 1 ? stem.string() : stem.string() + "-" + std::to_string(n));
  }
  return names;
}

std::string batch_hash(const std::filesystem::path& file, const std::string& options) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  const auto mix = [&h](const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      h ^= static_cast<unsigned char>(data[i]);
      h *= 0x100000001b3ull;
    }
  };
  std::ifstream in(file, std::ios::binary);
  if (!in) return "unreadable";
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) mix(buffer, static_cast<std::size_t>(in.gcount()));
  mix("\0", 1);
  mix(options.data(), options.size());
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

std::map<std::string, BatchRow> read_batch_manifest(const std::filesystem::path& manifest) {
  std::map<std::string, BatchRow> rows;
  std::ifstream in(manifest);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, '\t');) f.push_back(field);
    if (f.size() < 8 || (f[1] != "ok" && f[1] != "failed")) continue;  // a line cut short by a crash
    BatchRow r;
    r.hash = f[0];
    r.status = f[1];
    r.seconds = std::atof(f[2].c_str());
    r.atoms = std::atoll(f[3].c_str());
    r.area = std::atof(f[4].c_str());
    r.volume = std::atof(f[5].c_str());
    r.cavities = std::atoll(f[6].c_str());
    r.input = f[7];
    if (f.size() > 8) r.message = f[8];
    rows[r.input] = r;
  }
  return rows;
}

std::string batch_manifest_line(const BatchRow& r) {
  std::string message = r.message;
  std::replace_if(message.begin(), message.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
  std::string input = r.input;
  std::replace_if(input.begin(), input.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
  return r.hash + "\t" + r.status + "\t" + number(r.seconds) + "\t" + std::to_string(r.atoms) + "\t" + number(r.area) +
         "\t" + number(r.volume) + "\t" + std::to_string(r.cavities) + "\t" + input + "\t" + message + "\n";
}

BatchResume resume_batch(const std::vector<std::filesystem::path>& inputs, const std::string& job_options,
                         const std::map<std::string, BatchRow>& manifest, bool retry_failed) {
  BatchResume resume;
  resume.rows.resize(inputs.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    BatchRow& row = resume.rows[k];
    row.input = inputs[k].string();
    row.hash = batch_hash(inputs[k], job_options);
    const auto found = manifest.find(row.input);
    if (found != manifest.end() && found->second.hash == row.hash && (found->second.status == "ok" || !retry_failed))
      row = found->second;  // finished before, with the same input and options
    else
      resume.pending.push_back(k);
  }
  return resume;
}

void record_batch_result(BatchRow& row, const BatchRow& result) {
  row.status = result.status;
  row.seconds = result.seconds;
  row.atoms = result.atoms;
  row.cavities = result.cavities;
  row.area = result.area;
  row.volume = result.volume;
  row.message = result.message;
}

std::string batch_summary_csv(const std::vector<BatchRow>& rows) {
  std::string out = "file,atoms,area,volume,cavities,seconds,status,message\n";
  for (const BatchRow& r : rows) {
    const bool ok = r.status == "ok";
    out += csv_field(r.input) + "," + (r.atoms >= 0 ? std::to_string(r.atoms) : "") + "," + (ok ? number(r.area) : "") +
           "," + (ok ? number(r.volume) : "") + "," + (r.cavities >= 0 ? std::to_string(r.cavities) : "") + "," +
           number(r.seconds) + "," + r.status + "," + csv_field(r.message) + "\n";
  }
  return out;
}

std::string batch_summary_jsonl(const std::vector<BatchRow>& rows) {
  std::string out;
  for (const BatchRow& r : rows) {
    const bool ok = r.status == "ok";
    out += "{\"file\": " + json_string(r.input) + ", \"atoms\": " + (r.atoms >= 0 ? std::to_string(r.atoms) : "null") +
           ", \"area\": " + (ok ? number(r.area) : "null") + ", \"volume\": " + (ok ? number(r.volume) : "null") +
           ", \"cavities\": " + (r.cavities >= 0 ? std::to_string(r.cavities) : "null") +
           ", \"seconds\": " + number(r.seconds) + ", \"status\": \"" + r.status + "\", \"message\": " +
           (r.message.empty() ? std::string("null") : json_string(r.message)) + "}\n";
  }
  return out;
}

std::optional<double> report_number(const std::string& json, const std::string& key) {
  const std::string pattern = "\"" + key + "\": ";
  const std::size_t at = json.find(pattern);
  if (at == std::string::npos) return std::nullopt;
  const char* start = json.c_str() + at + pattern.size();
  char* end = nullptr;
  const double value = std::strtod(start, &end);
  if (end == start) return std::nullopt;
  return value;
}

}  // namespace molsurf::io
