#include "stcontact/io/json_writer.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <stdexcept>

namespace stc {

struct JsonObject::Document {
  nlohmann::ordered_json json;
};

namespace {

using nlohmann::ordered_json;

/// Strings are UTF-8 from the scene and the program; a byte sequence that is not valid UTF-8 (a
/// path, say) is written with U+FFFD instead of stopping the output.
std::string dumped(const ordered_json& json, int indent) {
  return json.dump(indent > 0 ? indent : -1, ' ', false, ordered_json::error_handler_t::replace);
}

ordered_json number(double value) { return std::isfinite(value) ? ordered_json(value) : ordered_json(nullptr); }

}  // namespace

std::string jsonString(std::string_view text) { return dumped(ordered_json(std::string(text)), 0); }

std::string jsonNumber(double value) { return dumped(number(value), 0); }

JsonObject::JsonObject() : document_(std::make_unique<Document>(Document{ordered_json::object()})) {}
JsonObject::~JsonObject() = default;
JsonObject::JsonObject(const JsonObject& other) : document_(std::make_unique<Document>(*other.document_)) {}
JsonObject::JsonObject(JsonObject&& other) noexcept : document_(std::move(other.document_)) {}

JsonObject& JsonObject::operator=(const JsonObject& other) {
  if (this != &other) document_ = std::make_unique<Document>(*other.document_);
  return *this;
}

JsonObject& JsonObject::operator=(JsonObject&& other) noexcept {
  document_ = std::move(other.document_);
  return *this;
}

JsonObject& JsonObject::add(std::string key, std::string_view value) {
  return addDocument(std::move(key), {ordered_json(std::string(value))});
}

JsonObject& JsonObject::add(std::string key, const char* value) {
  return addDocument(std::move(key), {value ? ordered_json(value) : ordered_json(nullptr)});
}

JsonObject& JsonObject::add(std::string key, double value) { return addDocument(std::move(key), {number(value)}); }

JsonObject& JsonObject::add(std::string key, bool value) { return addDocument(std::move(key), {ordered_json(value)}); }

JsonObject& JsonObject::add(std::string key, std::nullopt_t) {
  return addDocument(std::move(key), {ordered_json(nullptr)});
}

JsonObject& JsonObject::add(std::string key, const JsonObject& value) {
  return addDocument(std::move(key), *value.document_);
}

JsonObject& JsonObject::add(std::string key, const std::vector<double>& values) {
  ordered_json array = ordered_json::array();
  for (double v : values) array.push_back(number(v));
  return addDocument(std::move(key), {std::move(array)});
}

JsonObject& JsonObject::add(std::string key, const std::vector<JsonObject>& values) {
  ordered_json array = ordered_json::array();
  for (const JsonObject& v : values) array.push_back(v.document_->json);
  return addDocument(std::move(key), {std::move(array)});
}

JsonObject& JsonObject::add(std::string key, const RawJson& value) {
  ordered_json parsed = ordered_json::parse(value.text, nullptr, false);
  if (parsed.is_discarded())
    throw std::invalid_argument("JSON key '" + key + "': raw value is empty or not valid JSON");
  return addDocument(std::move(key), {std::move(parsed)});
}

JsonObject& JsonObject::addSigned(std::string key, long long value) {
  return addDocument(std::move(key), {ordered_json(value)});
}

JsonObject& JsonObject::addUnsigned(std::string key, unsigned long long value) {
  return addDocument(std::move(key), {ordered_json(value)});
}

JsonObject& JsonObject::addDocument(std::string key, Document value) {
  if (document_->json.contains(key)) throw std::invalid_argument("JSON key '" + key + "' added twice");
  document_->json[std::move(key)] = std::move(value.json);
  return *this;
}

std::string JsonObject::str(int indent) const { return dumped(document_->json, indent) + (indent > 0 ? "\n" : ""); }

bool JsonObject::empty() const { return document_->json.empty(); }

}  // namespace stc
