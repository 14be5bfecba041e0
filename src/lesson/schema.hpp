#pragma once
// Every key a lesson file may hold, per table, with its type and default. The parser
// accepts exactly these; lessons/README.md says what each means (a test checks that it
// has a row for every key here, with this type and default).
#include <span>
#include <string_view>

#include "toml/toml_table.hpp"

namespace linkage::lesson {

/// Top-level keys of a lesson file.
[[nodiscard]] std::span<const KeySpec> lesson_keys();
/// Keys every step has ("kind", "heading").
[[nodiscard]] std::span<const KeySpec> common_step_keys();
/// Keys of a simulation run: allowed on simulate, render, plot and compare steps and in
/// their `runs` entries (besides the thirteen input names, which override the inputs
/// for that run only).
[[nodiscard]] std::span<const KeySpec> run_keys();
/// Keys only a `runs` entry has ("label", "series").
[[nodiscard]] std::span<const KeySpec> run_entry_keys();
/// Keys of a render step's `captions` entry ("at", "text").
[[nodiscard]] std::span<const KeySpec> caption_entry_keys();
/// The keys particular to a kind of step (without the common and run keys).
[[nodiscard]] std::span<const KeySpec> step_keys(std::string_view kind);
/// Whether a kind of step takes the run keys.
[[nodiscard]] bool takes_run_keys(std::string_view kind);

}  // namespace linkage::lesson
