#include "plexus/scenario/expectation.hpp"

#include <cmath>
#include <sstream>

namespace plexus::scenario {

bool Expectation::holds(double value) const {
  if (std::isnan(value)) return false;
  switch (op) {
    case Op::le: return value <= bound;
    case Op::ge: return value >= bound;
    case Op::lt: return value < bound;
    case Op::gt: return value > bound;
    case Op::eq: return value == bound;
  }
  return false;
}

std::string expectation_result(const Expectation& e, double value) {
  if (e.holds(value)) return "pass";
  return e.inconsistent.empty() ? "FAIL" : kInconsistentResult;
}

std::string worse_result(const std::string& a, const std::string& b) {
  for (const char* r : {"FAIL", kInconsistentResult, "pass"})
    if (a == r || b == r) return r;
  return a;
}

const char* Expectation::op_text() const {
  switch (op) {
    case Op::le: return "<=";
    case Op::ge: return ">=";
    case Op::lt: return "<";
    case Op::gt: return ">";
    case Op::eq: return "==";
  }
  return "?";
}

std::string Expectation::text() const {
  std::ostringstream s;
  s.precision(17);
  s << op_text() << ' ' << bound;
  return s.str();
}

bool parse_expectation(const std::string& metric, const std::string& text, Expectation& out) {
  std::size_t i = text.find_first_not_of(' ');
  if (i == std::string::npos) return false;
  static const std::pair<const char*, Expectation::Op> kOps[] = {{"<=", Expectation::Op::le},
                                                                 {">=", Expectation::Op::ge},
                                                                 {"==", Expectation::Op::eq},
                                                                 {"<", Expectation::Op::lt},
                                                                 {">", Expectation::Op::gt}};
  for (const auto& [sym, op] : kOps) {
    const std::string s = sym;
    if (text.compare(i, s.size(), s) != 0) continue;
    const std::string rest = text.substr(i + s.size());
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(rest, &used);
    } catch (const std::exception&) {
      return false;
    }
    if (rest.find_first_not_of(' ', used) != std::string::npos || !std::isfinite(v)) return false;
    out = Expectation{metric, op, v, {}};
    return true;
  }
  return false;
}

}  // namespace plexus::scenario
