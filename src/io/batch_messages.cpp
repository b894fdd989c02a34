#include "io/batch_messages.hpp"

#include <charconv>
#include <cstdint>
#include <cstring>
#include <vector>

namespace molsurf::io {

namespace {

// Fields as a count of bytes, a colon, the bytes: any byte may appear in a field.
void put(std::string& out, std::string_view field) {
  out += std::to_string(field.size());
  out += ':';
  out += field;
}

template <class Number>
void put_number(std::string& out, Number value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;  // shortest round trip
  put(out, std::string_view(text, static_cast<std::size_t>(end - text)));
}

std::optional<std::vector<std::string_view>> fields(std::string_view bytes) {
  std::vector<std::string_view> out;
  while (!bytes.empty()) {
    std::size_t length = 0;
    const auto [colon, error] = std::from_chars(bytes.data(), bytes.data() + bytes.size(), length);
    if (error != std::errc() || colon == bytes.data() + bytes.size() || *colon != ':') return std::nullopt;
    const auto start = static_cast<std::size_t>(colon - bytes.data()) + 1;
    if (length > bytes.size() - start) return std::nullopt;
    out.push_back(bytes.substr(start, length));
    bytes.remove_prefix(start + length);
  }
  return out;
}

template <class Number>
bool get_number(std::string_view text, Number& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc() && end == text.data() + text.size();
}

}  // namespace

std::string batch_job_bytes(const BatchJob& job) {
  std::string out;
  put_number(out, job.index);
  put(out, job.input);
  put(out, job.name);
  return out;
}

std::optional<BatchJob> batch_job_from_bytes(std::string_view bytes) {
  const auto f = fields(bytes);
  BatchJob job;
  if (!f || f->size() != 3 || !get_number((*f)[0], job.index)) return std::nullopt;
  job.input = (*f)[1];
  job.name = (*f)[2];
  return job;
}

std::string batch_result_bytes(std::size_t index, const BatchRow& row) {
  std::string out;
  put_number(out, index);
  for (const std::string* text : {&row.input, &row.hash, &row.status, &row.message}) put(out, *text);
  put_number(out, row.seconds);
  put_number(out, row.atoms);
  put_number(out, row.cavities);
  put_number(out, row.area);
  put_number(out, row.volume);
  return out;
}

std::optional<std::pair<std::size_t, BatchRow>> batch_result_from_bytes(std::string_view bytes) {
  const auto f = fields(bytes);
  std::pair<std::size_t, BatchRow> result;
  BatchRow& row = result.second;
  if (!f || f->size() != 10 || !get_number((*f)[0], result.first)) return std::nullopt;
  row.input = (*f)[1];
  row.hash = (*f)[2];
  row.status = (*f)[3];
  row.message = (*f)[4];
  if (!get_number((*f)[5], row.seconds) || !get_number((*f)[6], row.atoms) || !get_number((*f)[7], row.cavities) ||
      !get_number((*f)[8], row.area) || !get_number((*f)[9], row.volume))
    return std::nullopt;
  return result;
}

}  // namespace molsurf::io
