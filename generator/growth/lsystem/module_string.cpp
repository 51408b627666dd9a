#include "lsystem.hpp"

#include "common/text_util.hpp"

namespace arbor::lsys {

void ModuleString::push(char symbol, std::initializer_list<double> values) {
  modules.push_back({symbol, static_cast<std::uint8_t>(values.size()), static_cast<std::uint32_t>(parameters.size())});
  parameters.insert(parameters.end(), values.begin(), values.end());
}

std::string ModuleString::text() const {
  std::string out;
  out.reserve(modules.size());
  for (const Module& m : modules) {
    out += m.symbol;
    if (m.count == 0) continue;
    out += '(';
    for (std::uint8_t i = 0; i < m.count; ++i) {
      if (i) out += ',';
      out += formatNumber(parameters[m.first + i]);
    }
    out += ')';
  }
  return out;
}

}  // namespace arbor::lsys
