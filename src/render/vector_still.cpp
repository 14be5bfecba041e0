#include "render/vector_still.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <fstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "render/cairo_util.hpp"

namespace linkage {
namespace {

// Cairo's write callback: appends to the temporary file's stream.
cairo_status_t write_to_stream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::ofstream*>(closure);
  out->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(length));
  return *out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

}  // namespace

void write_vector_still(const std::function<void(cairo_t*)>& paint, OutputKind kind, int width, int height,
                        const std::filesystem::path& target, const std::string& origin) {
  if (kind != OutputKind::svg && kind != OutputKind::pdf)
    throw Error::failure("write_vector_still: not a vector format");
  AtomicFile file(target, origin, true);
  cairo::SurfacePtr surface;
  if (kind == OutputKind::svg) {
    surface.reset(cairo_svg_surface_create_for_stream(write_to_stream, &file.stream(), width, height));
    cairo::check(surface.get(), "cannot start the SVG " + target.string());
    cairo_svg_surface_restrict_to_version(surface.get(), CAIRO_SVG_VERSION_1_1);
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
  } else {
    surface.reset(cairo_pdf_surface_create_for_stream(write_to_stream, &file.stream(), width, height));
    cairo::check(surface.get(), "cannot start the PDF " + target.string());
    // A fixed date, so the same figure gives the same bytes.
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATOR, "linkage render");
  }
  {
    const cairo::ContextPtr cr = cairo::context(surface.get());
    paint(cr.get());
  }
  cairo_surface_finish(surface.get());
  cairo::check(surface.get(), "cannot write " + target.string());
  file.commit();
}

}  // namespace linkage
