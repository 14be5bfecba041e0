#include "encode/html_page.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/markup_escape.hpp"
#include "core/sha256.hpp"

namespace linkage {
namespace {

std::string between(const std::string& text, const std::string& open, const std::string& close) {
  const std::size_t a = text.find(open);
  if (a == std::string::npos) return {};
  const std::size_t b = text.find(close, a + open.size());
  return b == std::string::npos ? std::string() : text.substr(a + open.size(), b - a - open.size());
}

std::string csp_source(const std::string& content) {
  const std::array<std::uint8_t, 32> digest = sha256(content);
  return "'sha256-" + base64(std::string(reinterpret_cast<const char*>(digest.data()), digest.size())) + "'";
}

TEST(HtmlPage, EscapesMarkupCharacters) {
  EXPECT_EQ(escape_markup("</script><script>alert(1)</script>"),
            "&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;");
  EXPECT_EQ(escape_markup("a & \"b\" 'c'"), "a &amp; &quot;b&quot; &#39;c&#39;");
  EXPECT_EQ(escape_markup("θ₁ = 0.1 rad"), "θ₁ = 0.1 rad");
}

// The policy allows exactly the page's own script and style (by their hashes), its empty
// icon, and nothing else: the page paints its frames itself, from no image.
TEST(HtmlPage, PolicyAllowsOnlyItsOwnScriptAndStyle) {
  const std::string page = html_page({"A <b>title</b>"}, R"({"width": 2})");
  const std::string policy = between(page, "http-equiv=\"Content-Security-Policy\" content=\"", "\"");
  ASSERT_FALSE(policy.empty());
  EXPECT_EQ(policy.rfind("default-src 'none'; ", 0), 0u) << policy;
  const std::string script = between(page, "\n<script>", "</script>");
  // Two style elements: the player's and the equations panel's.
  const std::string style = between(page, "<style>", "</style>");
  const std::string panel_style = between(page, "</style>\n<style>", "</style>");
  ASSERT_FALSE(script.empty());
  ASSERT_FALSE(style.empty());
  ASSERT_FALSE(panel_style.empty());
  EXPECT_NE(policy.find("script-src " + csp_source(script) + ";"), std::string::npos) << policy;
  EXPECT_NE(policy.find("style-src " + csp_source(style) + " " + csp_source(panel_style) + ";"), std::string::npos)
      << policy;
  // No image but the empty icon: the frames are painted, not decoded from blob: images.
  EXPECT_NE(policy.find("; img-src data:;"), std::string::npos) << policy;
  EXPECT_EQ(policy.find("blob:"), std::string::npos) << policy;
  EXPECT_EQ(policy.find("http"), std::string::npos) << policy;
  EXPECT_EQ(policy.find("unsafe"), std::string::npos) << policy;
  // The title only escaped, in the title and the heading.
  EXPECT_EQ(page.find("<b>"), std::string::npos);
  EXPECT_NE(page.find("<title>A &lt;b&gt;title&lt;/b&gt;</title>"), std::string::npos);
  EXPECT_NE(page.find("<h1 id=\"title\">A &lt;b&gt;title&lt;/b&gt;</h1>"), std::string::npos);
}

// The equations (HTML the report's renderer escaped) go into a panel that can be hidden,
// as they are; without them there is no panel.
TEST(HtmlPage, EquationsInTheirOwnPanel) {
  PageText text{"Four-bar", "<h1>Worked solution</h1>\n<p><math><mi>x</mi></math></p>\n"};
  const std::string page = html_page(text, "{}");
  EXPECT_NE(page.find("<details id=\"equations\" open><summary>Equations</summary><div id=\"equations-body\">\n"
                      "<h1>Worked solution</h1>\n<p><math><mi>x</mi></math></p>\n</div></details>"),
            std::string::npos);
  // After the player (its canvas), inside the view that lays them out side by side.
  EXPECT_LT(page.find("<div id=\"view\">"), page.find("<canvas"));
  EXPECT_LT(page.find("<canvas"), page.find("<details"));
  text.equations.clear();
  EXPECT_EQ(html_page(text, "{}").find("<details"), std::string::npos);
}

}  // namespace
}  // namespace linkage
