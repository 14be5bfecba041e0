#pragma once
// `linkage solve --format text`: the worked solution for a terminal, every line at
// most ReportOptions::width display columns where the content allows.
#include <string>

#include "report/worked_solution.hpp"

namespace linkage {

/// The worked solution as aligned plain text in options.text_style (unicode or ascii).
[[nodiscard]] std::string text_report(const WorkedSolution& worked, const ReportOptions& options);

/// Unicode when the environment's locale (LC_ALL, LC_CTYPE, LANG) uses UTF-8, else
/// ASCII. Reads the locale with setlocale(LC_CTYPE, "") and restores the previous one.
[[nodiscard]] expr::Style text_style_from_locale();

}  // namespace linkage
