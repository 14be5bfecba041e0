#include "render/cairo_util.hpp"

#include <string>

#include "core/error.hpp"

namespace linkage::cairo {
namespace {
void throw_unless_success(cairo_status_t status, std::string_view what) {
  if (status != CAIRO_STATUS_SUCCESS) throw Error::failure(std::string(what) + ": " + cairo_status_to_string(status));
}
}  // namespace

void check(cairo_surface_t* surface, std::string_view what) {
  throw_unless_success(cairo_surface_status(surface), what);
}
void check(cairo_t* context, std::string_view what) { throw_unless_success(cairo_status(context), what); }

SurfacePtr image_surface(int width, int height) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
  check(surface.get(), "cannot create a drawing surface");
  return surface;
}

SurfacePtr surface_for(Frame& frame) {
  if (frame.stride != cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, frame.width))
    throw Error::failure("frame stride " + std::to_string(frame.stride) + " does not suit Cairo for width " +
                         std::to_string(frame.width));
  SurfacePtr surface(cairo_image_surface_create_for_data(frame.pixels.data(), CAIRO_FORMAT_ARGB32, frame.width,
                                                         frame.height, frame.stride));
  check(surface.get(), "cannot draw into a frame");
  return surface;
}

ContextPtr context(cairo_surface_t* surface) {
  ContextPtr cr(cairo_create(surface));
  check(cr.get(), "cannot create a drawing context");
  return cr;
}

}  // namespace linkage::cairo
