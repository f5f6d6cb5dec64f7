// Reading a data file's fields (lua_data.h values) with errors at the value's file:line:column:
// the manifest's and the sound bank's readers share these, so both say the same thing the same way.
#pragma once
#include <initializer_list>
#include <string>
#include <vector>

#include "platon/core/lua_data.h"

namespace platon::core {

std::string placeText(const std::string& file, const DataValue& v);
[[noreturn]] void fieldError(const std::string& file, const DataValue& v, const std::string& reason);
// The string at `key`, or `fallback` when absent; any other type is an error.
std::string stringField(const std::string& file, const DataValue& table, const char* key, std::string fallback);
// A number as messages show it (%.15g).
std::string shown(double v);
// The number at `key` within [low, high], or `fallback` when absent.
double numberField(const std::string& file, const DataValue& table, const char* key, double fallback, double low,
                   double high);
// A whole number within [low, high] (an edge, a seed, a limit: 4096.7 is a mistake, not 4096).
double wholeField(const std::string& file, const DataValue& table, const char* key, double fallback, double low,
                  double high);
// Every key of `table` is one of `known`, or an error at the first that is not, listing them.
void checkKeys(const std::string& file, const DataValue& table, std::initializer_list<const char*> known);
void checkKeys(const std::string& file, const DataValue& table, const std::vector<std::string>& known);

}  // namespace platon::core
