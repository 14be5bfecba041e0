#pragma once
// A still as a vector figure (SVG or PDF) through Cairo's vector surfaces, for papers
// and handouts: every line, fill and glyph stays a shape, nothing is a bitmap. The
// file appears whole or not at all (core/atomic_file.hpp).
#include <cairo.h>

#include <filesystem>
#include <functional>
#include <string>

#include "render/settings.hpp"

namespace linkage {

/// Draws a still into `target` as `kind` (svg or pdf), width x height units (SVG pixels,
/// PDF points), with `paint` drawing the whole figure onto the vector surface's context.
/// `origin` names the flag in errors.
void write_vector_still(const std::function<void(cairo_t*)>& paint, OutputKind kind, int width, int height,
                        const std::filesystem::path& target, const std::string& origin);

}  // namespace linkage
