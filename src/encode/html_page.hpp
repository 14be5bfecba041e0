#pragma once
// One self-contained HTML page that plays a clip (`linkage render --out clip.html`): no
// network at all (a Content-Security-Policy allowing only its own inline script and style),
// so it works from file://, inside a learning-management system or offline. The clip's data
// (its frames' layers as Cairo's drawing operations, their times, the arrows' values) is gzip-compressed and
// base64-encoded inside the page; the browser's own DecompressionStream('gzip') opens it. The page's script paints the
// frames' layers onto a canvas and gives play/pause, a time slider, speed, frame steps (keys <- -> and space), layer
// toggles, the value of the arrow or the panel's curve under the cursor, and the motion's table to download as CSV; it
// exposes window.linkagePage for tests. Beside the player (below it on a narrow window), a panel that can be hidden
// shows the worked equations of the clip's case, its math as MathML.
#include <filesystem>
#include <string>

namespace linkage {

/// The words the page shows around the clip; each is escaped where the page puts it.
struct PageText {
  std::string title;
  /// The worked equations of the clip's case as HTML, escaped already (report's
  /// markdown_to_html); shown in a panel beside the clip, none when empty.
  std::string equations{};
};

/// The page's HTML for `data` (JSON: width, height, fps, speed, times, layers, toggles,
/// drawings, styles, gradients, glyphs, paths, frames, arrows, panel, csv, csvName; see
/// pipeline/clip_page.cpp and encode/canvas_ops.hpp).
[[nodiscard]] std::string html_page(const PageText& text, const std::string& data);

/// Writes html_page(text, data) to `target` atomically; `setting` names the output in errors.
void write_html_page(const PageText& text, const std::string& data, const std::filesystem::path& target,
                     const std::string& setting);

}  // namespace linkage
