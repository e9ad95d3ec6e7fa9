#include "framework/model/residual_signature.hpp"

#include <cmath>
#include <cstdio>

namespace hystbench {
namespace {

std::string number(double x) {
  if (!std::isfinite(x)) return "–";
  char buf[32];
  if (x == std::round(x) && std::abs(x) < 1e6)
    std::snprintf(buf, sizeof buf, "%.0f", x);
  else
    std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

void replace_all(std::string& text, const std::string& key, const std::string& by) {
  for (auto at = text.find(key); at != std::string::npos; at = text.find(key, at + by.size()))
    text.replace(at, key.size(), by);
}

}  // namespace

std::string cite(const ResidualSignature& signature, const SignatureValue& v) {
  if (!std::isfinite(v.value)) return "";
  std::string text = signature.sentence;
  replace_all(text, "{value}", number(v.value));
  for (const auto& [name, x] : v.details) replace_all(text, "{" + name + "}", number(x));
  return text;
}

}  // namespace hystbench
