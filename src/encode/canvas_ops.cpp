#include "encode/canvas_ops.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace linkage {
namespace {

double number(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data())
    throw std::logic_error("a page's layer: \"" + std::string(text) + "\" in Cairo's SVG is not a number");
  return value;
}

double hundredths_rounded(double v) { return std::round(v * 100) / 100 + 0.0; }  // + 0.0: no -0

// n hundredths as a decimal number, its trailing zeros dropped: 1250 "12.5", -300 "-3".
std::string hundredths(long n) {
  std::string out = n < 0 ? "-" : "";
  const unsigned long magnitude = n < 0 ? 0UL - static_cast<unsigned long>(n) : static_cast<unsigned long>(n);
  out += std::to_string(magnitude / 100);
  const unsigned long fraction = magnitude % 100;
  if (fraction != 0) {
    out += '.';
    out += static_cast<char>('0' + fraction / 10);
    if (fraction % 10 != 0) out += static_cast<char>('0' + fraction % 10);
  }
  return out;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (std::size_t i = 0; i <= text.size();) {
    const std::size_t next = std::min(text.find(separator, i), text.size());
    if (next > i) parts.push_back(text.substr(i, next - i));
    i = next + 1;
  }
  return parts;
}

/// One tag of Cairo's SVG: its name and attributes (always double-quoted there).
struct Tag {
  std::string_view name;
  bool closing = false;
  std::vector<std::pair<std::string_view, std::string_view>> attributes;

  [[nodiscard]] std::string_view get(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return v;
    return {};
  }
};

/// The next element tag at or after `at` (declarations and processing instructions skipped);
/// false at the end.
bool next_tag(std::string_view svg, std::size_t& at, Tag& tag) {
  while (true) {
    const std::size_t open = svg.find('<', at);
    if (open == std::string_view::npos) return false;
    const std::size_t close = svg.find('>', open);
    if (close == std::string_view::npos) throw std::logic_error("a page's layer: Cairo's SVG ends inside a tag");
    at = close + 1;
    std::string_view inside = svg.substr(open + 1, close - open - 1);
    if (inside.empty() || inside.front() == '?' || inside.front() == '!') continue;
    tag = Tag{};
    if (inside.front() == '/') {
      tag.closing = true;
      inside.remove_prefix(1);
    }
    if (!inside.empty() && inside.back() == '/') inside.remove_suffix(1);
    const std::size_t name_end = std::min(inside.find_first_of(" \n\t"), inside.size());
    tag.name = inside.substr(0, name_end);
    for (std::size_t i = name_end; i < inside.size();) {
      const std::size_t equals = inside.find("=\"", i);
      if (equals == std::string_view::npos) break;
      const std::size_t end = inside.find('"', equals + 2);
      if (end == std::string_view::npos) throw std::logic_error("a page's layer: an attribute of Cairo's SVG is open");
      std::string_view key = inside.substr(i, equals - i);
      while (!key.empty() && (key.front() == ' ' || key.front() == '\n' || key.front() == '\t')) key.remove_prefix(1);
      tag.attributes.emplace_back(key, inside.substr(equals + 2, end - equals - 2));
      i = end + 1;
    }
    return true;
  }
}

/// An SVG style attribute's properties, later ones (an element's own) over earlier (inherited).
using Properties = std::map<std::string, std::string, std::less<>>;

void add_style(Properties& to, std::string_view style) {
  for (const std::string_view declaration : split(style, ';')) {
    const std::size_t colon = declaration.find(':');
    if (colon == std::string_view::npos) continue;
    std::string_view key = declaration.substr(0, colon), value = declaration.substr(colon + 1);
    while (!key.empty() && key.front() == ' ') key.remove_prefix(1);
    while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
    to[std::string(key)] = std::string(value);
  }
}

std::string_view property(const Properties& p, std::string_view key, std::string_view fallback) {
  const auto it = p.find(key);
  return it == p.end() ? fallback : std::string_view(it->second);
}

/// Cairo's "rgb(r%,g%,b%)" with its opacity as a CSS colour the canvas takes.
std::string css_colour(std::string_view colour, std::string_view opacity) {
  if (colour.rfind("rgb(", 0) != 0 || colour.back() != ')')
    throw std::logic_error("a page's layer: the colour \"" + std::string(colour) + "\" is not Cairo's rgb(%)");
  const std::vector<std::string_view> parts = split(colour.substr(4, colour.size() - 5), ',');
  if (parts.size() != 3)
    throw std::logic_error("a page's layer: the colour \"" + std::string(colour) + "\" is not Cairo's rgb(%)");
  std::string out = "rgba(";
  for (const std::string_view part : parts) {
    const double percent = number(part.substr(0, part.find('%')));
    out.append(std::to_string(std::lround(std::clamp(percent, 0.0, 100.0) * 2.55))).append(",");
  }
  return out.append(opacity).append(")");
}

std::string rect_data(const Tag& tag) {
  const double x = number(tag.get("x")), y = number(tag.get("y"));
  const double w = number(tag.get("width")), h = number(tag.get("height"));
  const auto point = [](double a, double b) { return std::to_string(a) + " " + std::to_string(b); };
  return "M " + point(x, y) + " L " + point(x + w, y) + " L " + point(x + w, y + h) + " L " + point(x, y + h) + " Z";
}

std::string_view reference(std::string_view url) {  // "url(#id)" -> "id"
  if (url.rfind("url(#", 0) != 0 || url.back() != ')')
    throw std::logic_error("a page's layer: \"" + std::string(url) + "\" is not a reference");
  return url.substr(5, url.size() - 6);
}

}  // namespace

std::string PathBook::compact(std::string_view data) {
  const std::vector<std::string_view> tokens = split(data, ' ');
  const auto value = [&](std::size_t i) { return i < tokens.size() ? number(tokens[i]) : 0.0; };
  std::string out, body;
  double start[2] = {0, 0};
  long current[2] = {0, 0};  // hundredths from the start
  const auto flush = [&] {
    const auto [entry, added] = index_.try_emplace(body, entries_.size());
    if (added) entries_.push_back(body);
    out.append(" @").append(std::to_string(entry->second));
    body.clear();
  };
  // A line (1 point) or a curve (3) from token i on: each point relative to where the
  // segment starts (SVG's l and c); the segment's end becomes the current point.
  const auto segment = [&](char letter, std::size_t i, int points) {
    if (!body.empty()) body += ' ';
    body += letter;
    std::array<long, 2> end{};
    for (int p = 0; p < points; ++p, i += 2) {
      end = {std::lround((value(i) - start[0]) * 100), std::lround((value(i + 1) - start[1]) * 100)};
      body.append(" ").append(hundredths(end[0] - current[0]));
      body.append(" ").append(hundredths(end[1] - current[1]));
    }
    current[0] = end[0];
    current[1] = end[1];
    return static_cast<std::size_t>(1 + 2 * points);
  };
  bool open = false;
  for (std::size_t i = 0; i < tokens.size();) {
    const std::string_view command = tokens[i];
    if (command == "M") {
      if (open) flush();
      start[0] = value(i + 1);
      start[1] = value(i + 2);
      current[0] = current[1] = 0;
      if (!out.empty()) out += ' ';
      out.append("M ").append(hundredths(std::lround(start[0] * 100)));
      out.append(" ").append(hundredths(std::lround(start[1] * 100)));
      open = true;
      i += 3;
    } else if (command == "L" && open) {
      i += segment('l', i + 1, 1);
    } else if (command == "C" && open) {
      i += segment('c', i + 1, 3);
    } else if (command == "Z" && open) {
      body.append(body.empty() ? "z" : " z");
      current[0] = current[1] = 0;
      i += 1;
    } else {  // not Cairo's: kept as it is
      return std::string(data);
    }
  }
  if (open) flush();
  return out;
}

std::size_t CanvasOps::style(const nlohmann::json& style) {
  const auto [at, added] = style_index_.try_emplace(style.dump(), styles_.size());
  if (added) styles_.push_back(style);
  return at->second;
}

std::size_t CanvasOps::gradient(const nlohmann::json& gradient) {
  const auto [at, added] = gradient_index_.try_emplace(gradient.dump(), gradients_.size());
  if (added) gradients_.push_back(gradient);
  return at->second;
}

std::size_t CanvasOps::glyph(const std::string& data) {
  const auto [at, added] = glyph_index_.try_emplace(data, glyphs_.size());
  if (added) glyphs_.push_back(data);
  return at->second;
}

/// Reads one layer's SVG: its definitions (glyphs, clip paths, gradients), then what it
/// draws, in order, into canvas operations.
class SvgLayerReader {
 public:
  explicit SvgLayerReader(CanvasOps& ops) : ops_(ops) {}

  nlohmann::json read(std::string_view svg) {
    std::size_t at = 0;
    Tag tag;
    groups_.clear();
    groups_.push_back(Group{});
    while (next_tag(svg, at, tag)) {
      if (defs_ > 0)
        definition(tag);
      else
        drawing(tag);
    }
    if (groups_.size() != 1) throw std::logic_error("a page's layer: Cairo's SVG leaves a group open");
    return std::move(groups_.front().ops);
  }

 private:
  struct Group {
    nlohmann::json ops = nlohmann::json::array();
    Properties inherited;
    std::string clip, rule;  // clip path data (compacted) and its rule, when clipped
  };
  enum class Definition { none, symbol, clip, gradient };

  void definition(const Tag& tag) {
    if (tag.name == "defs") {
      defs_ += tag.closing ? -1 : 1;
    } else if (tag.name == "g") {  // Cairo groups its glyph symbols
    } else if (tag.name == "symbol" || tag.name == "clipPath" || tag.name == "linearGradient") {
      if (tag.closing) {
        finish_definition();
        return;
      }
      id_ = tag.get("id");
      data_.clear();
      if (tag.name == "symbol") {
        kind_ = Definition::symbol;
      } else if (tag.name == "clipPath") {
        kind_ = Definition::clip;
      } else {
        kind_ = Definition::gradient;
        if (tag.get("gradientUnits") != "userSpaceOnUse" || !tag.get("gradientTransform").empty())
          throw std::logic_error("a page's layer: a gradient not in user space");
        gradient_ = {
            {"line", {number(tag.get("x1")), number(tag.get("y1")), number(tag.get("x2")), number(tag.get("y2"))}},
            {"stops", nlohmann::json::array()}};
      }
    } else if (tag.name == "path" && !tag.closing) {
      if (!tag.get("transform").empty()) throw std::logic_error("a page's layer: a transformed path in a definition");
      if (!data_.empty()) data_ += ' ';
      data_ += tag.get("d");
    } else if (tag.name == "rect" && !tag.closing) {
      if (!data_.empty()) data_ += ' ';
      data_ += rect_data(tag);
    } else if (tag.name == "stop" && !tag.closing && kind_ == Definition::gradient) {
      Properties p;
      add_style(p, tag.get("style"));
      gradient_["stops"].push_back(
          {number(tag.get("offset")), css_colour(property(p, "stop-color", ""), property(p, "stop-opacity", "1"))});
    } else if (!tag.closing) {
      throw std::logic_error("a page's layer: the page cannot draw Cairo's <" + std::string(tag.name) +
                             "> in a definition");
    }
  }

  void finish_definition() {
    switch (kind_) {
      case Definition::symbol:
        symbols_[std::string(id_)] = data_;
        break;
      case Definition::clip:
        clips_[std::string(id_)] = data_;
        break;
      case Definition::gradient:
        gradients_[std::string(id_)] = ops_.gradient(gradient_);
        break;
      case Definition::none:
        break;
    }
    kind_ = Definition::none;
  }

  void drawing(const Tag& tag) {
    if (tag.name == "defs") {
      defs_ += tag.closing ? -1 : 1;
    } else if (tag.name == "svg") {  // the document: what it holds is drawn
    } else if (tag.name == "g") {
      tag.closing ? close_group() : open_group(tag);
    } else if (tag.closing) {  // the end of a path, rect or use: drawn at its start
    } else if (tag.name == "path" || tag.name == "rect") {
      Properties p = groups_.back().inherited;
      add_style(p, tag.get("style"));
      const std::string data = tag.name == "rect" ? rect_data(tag) : std::string(tag.get("d"));
      if (data.empty()) return;
      nlohmann::json op = {"p", ops_.style(resolve(p)), ops_.book_.compact(data)};
      if (const std::string_view transform = tag.get("transform"); !transform.empty()) {
        if (transform.rfind("matrix(", 0) != 0 || transform.back() != ')')
          throw std::logic_error("a page's layer: the transform \"" + std::string(transform) + "\"");
        nlohmann::json matrix = nlohmann::json::array();
        for (const std::string_view v : split(transform.substr(7, transform.size() - 8), ','))
          matrix.push_back(number(v));
        if (matrix.size() != 6)
          throw std::logic_error("a page's layer: the transform \"" + std::string(transform) + "\"");
        op.push_back(std::move(matrix));
      }
      groups_.back().ops.push_back(std::move(op));
    } else if (tag.name == "use") {
      std::string_view href = tag.get("xlink:href");
      if (href.empty() || href.front() != '#') throw std::logic_error("a page's layer: a <use> of no symbol");
      const auto symbol = symbols_.find(std::string(href.substr(1)));
      if (symbol == symbols_.end())
        throw std::logic_error("a page's layer: a <use> of \"" + std::string(href) + "\", not a glyph");
      if (symbol->second.empty()) return;  // a space
      const std::size_t glyph = ops_.glyph(ops_.book_.compact(symbol->second));
      const std::size_t style = ops_.style(resolve(groups_.back().inherited));
      nlohmann::json& ops = groups_.back().ops;
      if (ops.empty() || ops.back()[0] != "g" || ops.back()[1] != style)
        ops.push_back({"g", style, nlohmann::json::array()});
      nlohmann::json& run = ops.back()[2];
      run.push_back(glyph);
      run.push_back(hundredths_rounded(number(tag.get("x"))));
      run.push_back(hundredths_rounded(number(tag.get("y"))));
    } else {
      throw std::logic_error("a page's layer: the page cannot draw Cairo's <" + std::string(tag.name) + ">");
    }
  }

  void open_group(const Tag& tag) {
    Group group;
    group.inherited = groups_.back().inherited;
    add_style(group.inherited, tag.get("style"));
    if (const std::string_view clip = tag.get("clip-path"); !clip.empty()) {
      const auto path = clips_.find(std::string(reference(clip)));
      if (path == clips_.end())
        throw std::logic_error("a page's layer: a clip \"" + std::string(clip) + "\" not defined");
      group.clip = ops_.book_.compact(path->second);
      group.rule = tag.get("clip-rule") == "evenodd" ? "evenodd" : "nonzero";
    }
    groups_.push_back(std::move(group));
  }

  void close_group() {
    if (groups_.size() < 2) throw std::logic_error("a page's layer: Cairo's SVG closes a group it did not open");
    Group group = std::move(groups_.back());
    groups_.pop_back();
    if (group.ops.empty()) return;
    nlohmann::json& to = groups_.back().ops;
    if (group.clip.empty()) {
      for (nlohmann::json& op : group.ops) to.push_back(std::move(op));
    } else {
      to.push_back({"c", group.clip, group.rule, std::move(group.ops)});
    }
  }

  /// An element's properties as the painter's style (SVG's defaults where none is given).
  nlohmann::json resolve(const Properties& p) {
    nlohmann::json style = nlohmann::json::object();
    const std::string_view fill = property(p, "fill", "rgb(0%,0%,0%)");
    if (fill.rfind("url(", 0) == 0) {
      const auto at = gradients_.find(std::string(reference(fill)));
      if (at == gradients_.end()) throw std::logic_error("a page's layer: the fill \"" + std::string(fill) + "\"");
      style["gradient"] = at->second;
    } else if (fill != "none") {
      style["fill"] = css_colour(fill, property(p, "fill-opacity", "1"));
    }
    if (property(p, "fill-rule", "nonzero") == "evenodd") style["rule"] = "evenodd";
    const std::string_view stroke = property(p, "stroke", "none");
    if (stroke == "none") return style;
    style["stroke"] = css_colour(stroke, property(p, "stroke-opacity", "1"));
    style["width"] = number(property(p, "stroke-width", "1"));
    style["cap"] = property(p, "stroke-linecap", "butt");
    style["join"] = property(p, "stroke-linejoin", "miter");
    style["miter"] = number(property(p, "stroke-miterlimit", "4"));
    if (const std::string_view dash = property(p, "stroke-dasharray", "none"); dash != "none") {
      style["dash"] = nlohmann::json::array();
      for (const std::string_view v : split(dash, ',')) style["dash"].push_back(number(v));
      style["offset"] = number(property(p, "stroke-dashoffset", "0"));
    }
    return style;
  }

  CanvasOps& ops_;
  std::vector<Group> groups_;
  int defs_ = 0;
  Definition kind_ = Definition::none;
  std::string_view id_;
  std::string data_;
  nlohmann::json gradient_;
  std::map<std::string, std::string, std::less<>> symbols_, clips_;
  std::map<std::string, std::size_t, std::less<>> gradients_;
};

nlohmann::json CanvasOps::layer(std::string_view svg) { return SvgLayerReader(*this).read(svg); }

}  // namespace linkage
