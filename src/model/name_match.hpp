#pragma once
// Moved to core (the value parsers of core and integrate suggest names too). Kept only
// for src/lesson/parse.cpp until it includes core/name_match.hpp; then delete this file.
#include "core/name_match.hpp"  // IWYU pragma: export
