#pragma once
// Owning pointers for Cairo objects and status checks that turn a Cairo failure into
// linkage::Error with Cairo's own words.
#include <cairo.h>

#include <memory>
#include <string_view>

#include "core/frame.hpp"

namespace linkage::cairo {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

/// Throws Error::failure "<what>: <cairo's message>" unless the surface is fine.
void check(cairo_surface_t* surface, std::string_view what);
/// Throws Error::failure "<what>: <cairo's message>" unless the context is fine.
void check(cairo_t* context, std::string_view what);

/// A new ARGB32 image surface (checked).
[[nodiscard]] SurfacePtr image_surface(int width, int height);
/// An ARGB32 surface drawing straight into `frame`'s pixels (checked); the frame must
/// outlive it and keep its buffer.
[[nodiscard]] SurfacePtr surface_for(Frame& frame);
/// A context on `surface` (checked).
[[nodiscard]] ContextPtr context(cairo_surface_t* surface);

}  // namespace linkage::cairo
