#include "framework/core/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/core/error.hpp"
#include "framework/core/text.hpp"

namespace hystbench {
namespace {


void check_number(const ParamSpec& spec, const nlohmann::json& value,
                  const std::string& where) {
  const std::string key = where + "." + spec.name;
  const bool integral = spec.type == ParamSpec::Type::Integer;
  if (!value.is_number() || (integral && !value.is_number_integer())) {
    throw InputError(key + ": expected " + (integral ? "an integer" : "a number") +
                     ", got " + value.dump());
  }
  const double v = value.get<double>();
  if (!std::isfinite(v) || v < spec.min || v > spec.max) {
    throw InputError(key + " = " + value.dump() + " is out of range; it must be in [" +
                     number_text(spec.min) + ", " + number_text(spec.max) + "]");
  }
}

void check_value(const ParamSpec& spec, const nlohmann::json& value,
                 const std::string& where) {
  const std::string key = where + "." + spec.name;
  switch (spec.type) {
    case ParamSpec::Type::Integer:
    case ParamSpec::Type::Real:
      check_number(spec, value, where);
      return;
    case ParamSpec::Type::Boolean:
      if (!value.is_boolean())
        throw InputError(key + ": expected true or false, got " + value.dump());
      return;
    case ParamSpec::Type::Choice:
      if (!value.is_string() ||
          std::find(spec.choices.begin(), spec.choices.end(), value.get<std::string>()) ==
              spec.choices.end())
        throw InputError(key + " = " + value.dump() + " is not valid; choose one of: " +
                         join(spec.choices));
      return;
    case ParamSpec::Type::Text:
      if (!value.is_string()) throw InputError(key + ": expected a string, got " + value.dump());
      return;
    case ParamSpec::Type::Object:
      if (!value.is_object()) throw InputError(key + ": expected a JSON object, got " + value.dump());
      return;
    case ParamSpec::Type::Array:
      if (!value.is_array()) throw InputError(key + ": expected a JSON array, got " + value.dump());
      return;
    case ParamSpec::Type::Range:
      read_range(value, key);
      return;
  }
}

}  // namespace

ParamSpec ParamSpec::integer(std::string name, nlohmann::json default_value, double min,
                             double max, std::string doc) {
  return {std::move(name), Type::Integer, std::move(default_value), min, max, {}, std::move(doc)};
}

ParamSpec ParamSpec::real(std::string name, nlohmann::json default_value, double min,
                          double max, std::string doc) {
  return {std::move(name), Type::Real, std::move(default_value), min, max, {}, std::move(doc)};
}

ParamSpec ParamSpec::choice(std::string name, std::string default_value,
                            std::vector<std::string> choices, std::string doc) {
  return {std::move(name), Type::Choice, std::move(default_value), 0, 0, std::move(choices),
          std::move(doc)};
}

ParamSpec ParamSpec::boolean(std::string name, bool default_value, std::string doc) {
  return {std::move(name), Type::Boolean, default_value, 0, 0, {}, std::move(doc)};
}

ParamSpec ParamSpec::text(std::string name, nlohmann::json default_value, std::string doc) {
  return {std::move(name), Type::Text, std::move(default_value), 0, 0, {}, std::move(doc)};
}

ParamSpec ParamSpec::object(std::string name, std::string doc) {
  return {std::move(name), Type::Object, nullptr, 0, 0, {}, std::move(doc)};
}

ParamSpec ParamSpec::array(std::string name, std::string doc) {
  return {std::move(name), Type::Array, nullptr, 0, 0, {}, std::move(doc)};
}

ParamSpec ParamSpec::range(std::string name, double lower, double upper, std::string doc) {
  return {std::move(name), Type::Range, {lower, upper}, 0, 0, {}, std::move(doc)};
}

ParamSpec& ParamSpec::require() {
  required = true;
  return *this;
}

namespace {

std::string interval(double lo, double hi) {
  const double huge = std::numeric_limits<double>::max();
  return lo == -huge && hi == huge ? "" : " in [" + number_text(lo) + ", " + number_text(hi) + "]";
}

std::string kind_of(const ParamSpec& p) {
  switch (p.type) {
    case ParamSpec::Type::Integer: return "integer" + interval(p.min, p.max);
    case ParamSpec::Type::Real: return "real" + interval(p.min, p.max);
    case ParamSpec::Type::Boolean: return "true/false";
    case ParamSpec::Type::Choice: return "one of {" + join(p.choices) + "}";
    case ParamSpec::Type::Text: return "text";
    case ParamSpec::Type::Object: return "JSON object";
    case ParamSpec::Type::Array: return "JSON array";
    case ParamSpec::Type::Range: return "[lower, upper]";
  }
  return "";
}

}  // namespace

std::string ParamSpec::describe_range() const {
  if (required) return kind_of(*this) + ", required";
  const bool structured = type == Type::Text || type == Type::Object || type == Type::Array;
  if (default_value.is_null()) return kind_of(*this) + (structured ? ", optional" : ", default auto");
  return kind_of(*this) + ", default " + default_value.dump();
}

bool Params::is_auto(const std::string& key) const { return at(key).is_null(); }
int Params::integer(const std::string& key) const { return at(key).get<int>(); }
double Params::real(const std::string& key) const { return at(key).get<double>(); }
std::string Params::text(const std::string& key) const { return at(key).get<std::string>(); }
bool Params::boolean(const std::string& key) const { return at(key).get<bool>(); }
std::pair<double, double> Params::range(const std::string& key) const {
  return {at(key)[0].get<double>(), at(key)[1].get<double>()};
}

std::pair<double, double> read_range(const nlohmann::json& value, const std::string& key) {
  const bool numbers = value.is_array() && value.size() == 2 && value[0].is_number() &&
                       value[1].is_number() && std::isfinite(value[0].get<double>()) &&
                       std::isfinite(value[1].get<double>());
  if (!numbers || !(value[0].get<double>() < value[1].get<double>()))
    throw InputError(key + " = " + value.dump() + ": give [lower, upper] with lower < upper");
  return {value[0].get<double>(), value[1].get<double>()};
}

const nlohmann::json& Params::at(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end())
    throw std::logic_error("plugin asked for undeclared parameter '" + key + "'");
  return *it;
}

void require_known_keys(const nlohmann::json& object, const std::vector<std::string>& allowed,
                        const std::string& where) {
  if (!object.is_object()) throw InputError(where + ": expected a JSON object, got " + object.dump());
  for (const auto& [key, value] : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw InputError(where + ": unknown key '" + key + "'; valid keys: " + join(allowed));
    }
  }
}

Params validate_params(const std::vector<ParamSpec>& specs, const nlohmann::json& given,
                       const std::string& where) {
  const nlohmann::json input = given.is_null() ? nlohmann::json::object() : given;
  std::vector<std::string> names;
  for (const auto& s : specs) names.push_back(s.name);
  require_known_keys(input, names, where);

  nlohmann::json values = nlohmann::json::object();
  for (const auto& spec : specs) {
    auto it = input.find(spec.name);
    if (spec.required && (it == input.end() || it->is_null()))
      throw InputError(where + "." + spec.name + ": missing; give " + spec.doc + " (" + kind_of(spec) + ")");
    if (it == input.end() || (it->is_null() && spec.default_value.is_null())) {
      values[spec.name] = spec.default_value;
      continue;
    }
    check_value(spec, *it, where);
    values[spec.name] = *it;
  }
  return Params(std::move(values));
}

std::string optional_text(const nlohmann::json& object, const std::string& key,
                          const std::string& fallback, const std::string& where) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_string()) throw InputError(where + "." + key + ": give a string");
  return object[key].get<std::string>();
}

double optional_number(const nlohmann::json& object, const std::string& key, double fallback,
                       double lo, double hi, const std::string& where) {
  if (!object.contains(key)) return fallback;
  const auto& v = object[key];
  if (!v.is_number() || !(v.get<double>() >= lo && v.get<double>() <= hi))
    throw InputError(where + "." + key + ": give a number in [" + number_text(lo) + ", " +
                     number_text(hi) + "]");
  return v.get<double>();
}

bool optional_flag(const nlohmann::json& object, const std::string& key, bool fallback,
                   const std::string& where) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_boolean()) throw InputError(where + "." + key + ": give true or false");
  return object[key].get<bool>();
}

}  // namespace hystbench
