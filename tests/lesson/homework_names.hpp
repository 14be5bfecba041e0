#pragma once
// The names a homework lesson's {{...}} and answers read: two-blocks.toml's quotable values
// (by its [aliases]) at its settings.
#include <memory>

#include "model/mechanism_toml.hpp"
#include "report/quotable_values.hpp"
#include "symbolic/system.hpp"

namespace linkage::lesson {

/// At two-blocks' own values (the homework's defaults).
inline const QuotableValues& homework_names() {
  static const QuotableValues names(std::make_shared<const sym::System>(load_mechanism("two-blocks")));
  return names;
}

}  // namespace linkage::lesson
