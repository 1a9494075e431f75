#include "src/io/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace stc {
namespace {

void appendEscaped(std::string& out, char c) {
  static constexpr char hex[] = "0123456789abcdef";
  switch (c) {
    case '"': out += "\\\""; return;
    case '\\': out += "\\\\"; return;
    case '\b': out += "\\b"; return;
    case '\f': out += "\\f"; return;
    case '\n': out += "\\n"; return;
    case '\r': out += "\\r"; return;
    case '\t': out += "\\t"; return;
    default: break;
  }
  const auto byte = static_cast<unsigned char>(c);
  if (byte < 0x20) {
    out += "\\u00";
    out += hex[byte >> 4];
    out += hex[byte & 0xF];
  } else {
    out += c;
  }
}

void newline(std::string& out, int indent, int depth) {
  if (indent <= 0) return;
  out += '\n';
  out.append(static_cast<std::size_t>(indent * depth), ' ');
}

/// Raw JSON spread over several lines gets the member's indentation after each line break (a
/// space on a single line); safe, since a line break in valid JSON is whitespace between tokens,
/// never inside a string.
void appendIndented(std::string& out, const std::string& text, int indent, int depth) {
  for (char c : text) {
    if (c != '\n')
      out += c;
    else if (indent > 0)
      newline(out, indent, depth);
    else
      out += ' ';
  }
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

}  // namespace

std::string jsonString(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out += '"';
  for (char c : text) appendEscaped(out, c);
  out += '"';
  return out;
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

JsonObject& JsonObject::add(std::string key, std::string_view value) {
  return addText(std::move(key), jsonString(value));
}

JsonObject& JsonObject::add(std::string key, const char* value) {
  return addText(std::move(key), value ? jsonString(value) : "null");
}

JsonObject& JsonObject::add(std::string key, double value) {
  return addText(std::move(key), jsonNumber(value));
}

JsonObject& JsonObject::add(std::string key, bool value) {
  return addText(std::move(key), value ? "true" : "false");
}

JsonObject& JsonObject::add(std::string key, std::nullopt_t) {
  return addText(std::move(key), "null");
}

JsonObject& JsonObject::add(std::string key, JsonObject value) {
  addText(std::move(key), {});
  members_.back().object = std::make_shared<const JsonObject>(std::move(value));
  return *this;
}

JsonObject& JsonObject::add(std::string key, const std::vector<double>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text += ", ";
    text += jsonNumber(values[i]);
  }
  return addText(std::move(key), text + "]");
}

JsonObject& JsonObject::add(std::string key, RawJson value) {
  std::string text = trimmed(value.text);
  if (text.empty()) throw std::invalid_argument("JSON key '" + key + "': raw value is empty");
  return addText(std::move(key), std::move(text));
}

JsonObject& JsonObject::addText(std::string key, std::string text) {
  for (const Member& member : members_)
    if (member.key == key) throw std::invalid_argument("JSON key '" + key + "' added twice");
  members_.push_back({std::move(key), std::move(text), nullptr});
  return *this;
}

std::string JsonObject::str(int indent) const {
  std::string out;
  write(out, indent, 0);
  if (indent > 0) out += '\n';
  return out;
}

void JsonObject::write(std::string& out, int indent, int depth) const {
  if (members_.empty()) {
    out += "{}";
    return;
  }
  out += '{';
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const Member& member = members_[i];
    if (i > 0) out += indent > 0 ? "," : ", ";
    newline(out, indent, depth + 1);
    out += jsonString(member.key);
    out += ": ";
    if (member.object)
      member.object->write(out, indent, depth + 1);
    else
      appendIndented(out, member.text, indent, depth + 1);
  }
  newline(out, indent, depth);
  out += '}';
}

}  // namespace stc
