#include "data_fields.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace platon::core {

std::string placeText(const std::string& file, const DataValue& v) {
  return file + ":" + std::to_string(v.line) + ":" + std::to_string(v.column);
}

[[noreturn]] void fieldError(const std::string& file, const DataValue& v, const std::string& reason) {
  throw std::runtime_error(file + ":" + std::to_string(v.line) + ":" + std::to_string(v.column) + ": " + reason);
}

std::string stringField(const std::string& file, const DataValue& table, const char* key, std::string fallback) {
  const DataValue* v = table.field(key);
  if (!v) return fallback;
  if (!v->isString()) fieldError(file, *v, std::string("'") + key + "' must be a string");
  return v->text;
}

std::string shown(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", v);
  return text;
}

double numberField(const std::string& file, const DataValue& table, const char* key, double fallback, double low,
                   double high) {
  const DataValue* v = table.field(key);
  if (!v) return fallback;
  if (!v->isNumber()) fieldError(file, *v, std::string("'") + key + "' must be a number");
  if (v->number < low || v->number > high)
    fieldError(
        file, *v,
        std::string("'") + key + "' must be within [" + shown(low) + ", " + shown(high) + "], not " + shown(v->number));
  return v->number;
}

double wholeField(const std::string& file, const DataValue& table, const char* key, double fallback, double low,
                  double high) {
  const double v = numberField(file, table, key, fallback, low, high);
  if (v != std::floor(v))
    fieldError(file, *table.field(key), std::string("'") + key + "' must be a whole number, not " + shown(v));
  return v;
}

void checkKeys(const std::string& file, const DataValue& table, std::initializer_list<const char*> known) {
  checkKeys(file, table, std::vector<std::string>(known.begin(), known.end()));
}

void checkKeys(const std::string& file, const DataValue& table, const std::vector<std::string>& known) {
  for (const DataEntry& e : table.entries) {
    bool ok = false;
    for (const std::string& k : known) ok = ok || (e.key.isString() && e.key.text == k);
    if (!ok) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      const std::string name = e.key.isString() ? dataKeyText(e.key) : "[" + dataKeyText(e.key) + "]";
      fieldError(file, e.key.line ? e.key : e.value, "unknown field " + name + " (known: " + list + ")");
    }
  }
}

}  // namespace platon::core
