#pragma once
// Declared parameters of a plugin, and validation of a user's JSON against
// them. A plugin lists what it accepts; the framework fills in defaults,
// rejects unknown keys (naming the valid ones) and out-of-range values
// (naming the range) before the plugin ever sees them.
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace hystbench {

struct ParamSpec {
  // Text, Object and Array are for problems, whose options include file
  // names and structured values that the problem reads itself.
  enum class Type { Integer, Real, Choice, Boolean, Text, Object, Array, Range };

  std::string name;
  Type type = Type::Real;
  // null means "auto": the plugin derives the value (e.g. from the dimension).
  nlohmann::json default_value;
  double min = 0.0;
  double max = 0.0;
  std::vector<std::string> choices;
  std::string doc;
  bool required = false;  // a missing key is an error, not the default

  static ParamSpec integer(std::string name, nlohmann::json default_value,
                           double min, double max, std::string doc);
  static ParamSpec real(std::string name, nlohmann::json default_value,
                        double min, double max, std::string doc);
  static ParamSpec choice(std::string name, std::string default_value,
                          std::vector<std::string> choices, std::string doc);
  static ParamSpec boolean(std::string name, bool default_value, std::string doc);
  // A string; null default: absent unless given.
  static ParamSpec text(std::string name, nlohmann::json default_value, std::string doc);
  // A JSON object or array, absent (null) unless given.
  static ParamSpec object(std::string name, std::string doc);
  static ParamSpec array(std::string name, std::string doc);
  // An interval [lower, upper] of finite numbers with lower < upper.
  static ParamSpec range(std::string name, double lower, double upper, std::string doc);
  // The same spec with a missing key refused, its doc naming what to give.
  ParamSpec& require();

  // "integer in [4, 100000], default auto" — used by `hystbench list`.
  std::string describe_range() const;
};

// Validated parameter values, defaults filled in.
class Params {
 public:
  Params() = default;
  explicit Params(nlohmann::json values) : values_(std::move(values)) {}

  bool is_auto(const std::string& key) const;
  int integer(const std::string& key) const;
  double real(const std::string& key) const;
  std::string text(const std::string& key) const;
  bool boolean(const std::string& key) const;
  std::pair<double, double> range(const std::string& key) const;
  // An Object or Array parameter as given (null when absent).
  const nlohmann::json& value(const std::string& key) const { return at(key); }
  const nlohmann::json& json() const { return values_; }

 private:
  const nlohmann::json& at(const std::string& key) const;
  nlohmann::json values_ = nlohmann::json::object();
};

// Checks `given` (a JSON object) against `specs`. `where` names the place in
// the user's file, e.g. "algorithms[0] (DE).params". Throws InputError.
Params validate_params(const std::vector<ParamSpec>& specs,
                       const nlohmann::json& given, const std::string& where);

// Optional keys of an input object with a fallback; InputError naming
// "where.key" and what is valid when the value has the wrong type or range.
std::string optional_text(const nlohmann::json& object, const std::string& key,
                          const std::string& fallback, const std::string& where);
double optional_number(const nlohmann::json& object, const std::string& key, double fallback,
                       double lo, double hi, const std::string& where);
bool optional_flag(const nlohmann::json& object, const std::string& key, bool fallback,
                   const std::string& where);

// [lower, upper] of finite numbers with lower < upper, or InputError naming `key`.
std::pair<double, double> read_range(const nlohmann::json& value, const std::string& key);

// Throws InputError if `object` has a key not in `allowed`, listing them.
void require_known_keys(const nlohmann::json& object,
                        const std::vector<std::string>& allowed,
                        const std::string& where);

}  // namespace hystbench
