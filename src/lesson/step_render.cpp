// The render step: runs `linkage render` with the step's options, so a lesson's clips
// and stills are exactly what the command gives, and the document can show the
// command that remakes each one.
#include <algorithm>

#include "core/error.hpp"
#include "core/number_format.hpp"
#include "lesson/runner_context.hpp"

namespace linkage::lesson {

std::vector<std::string> render_arguments(const RenderStep& render, Quality quality, const std::filesystem::path& out_dir) {
  std::vector<std::string> args{"render"};
  const Inputs defaults;
  for (const InputKey& key : kInputKeys)
    if (render.run.inputs.value(key) != defaults.value(key)) {
      args.emplace_back(key.flag);
      args.push_back(format_roundtrip(render.run.inputs.value(key)));
    }
  const bool draft = quality == Quality::draft;
  for (std::size_t i = 0; i + 1 < render.flags.size(); i += 2) {
    const std::string& flag = render.flags[i];
    const bool input = std::any_of(kInputKeys.begin(), kInputKeys.end(), [&](const InputKey& k) { return k.flag == flag; });
    if (input) continue;  // already given, with the values of earlier set steps
    if (draft && (flag == "--quality" || flag == "--size" || flag == "--fps")) continue;
    args.push_back(flag);
    args.push_back(render.flags[i + 1]);
  }
  if (draft) {
    args.insert(args.end(), {"--size", std::to_string(kDraftWidth) + "x" + std::to_string(kDraftHeight), "--fps",
                             std::to_string(std::min(render.settings.fps, kDraftFps))});
  }
  args.emplace_back("--out");
  args.push_back((out_dir / render.out).string());
  return args;
}

std::string command_line(const std::vector<std::string>& args) {
  std::string line = "linkage";
  for (const std::string& a : args) {
    const bool plain = !a.empty() && std::all_of(a.begin(), a.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("-_.,/:=+").find(c) != std::string_view::npos;
    });
    line += ' ';
    if (plain) {
      line += a;
      continue;
    }
    line += '\'';
    for (char c : a) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

void run_render(RunContext& c, const Step& step, const RenderStep& s) {
  c.cached(step, [&] {
    if (!c.options.run_linkage) throw Error::failure("a render step needs the linkage program to run `linkage render`");
    c.options.run_linkage(render_arguments(s, c.options.quality, c.options.out_dir));
    return nlohmann::json::object();
  });
  const FigureRef::Kind kind = is_still(s.kind) ? FigureRef::Kind::image : FigureRef::Kind::video;
  c.both([&](Writer& w) { w.figure(c.figure(s.out, kind, s.caption)); });
  // Lecturers can remake (or vary) any clip by hand: the document shows the command.
  c.document->markdown("<sub>Made with `" + command_line(render_arguments(s, c.options.quality, {})) + "`</sub>");
}

}  // namespace linkage::lesson
