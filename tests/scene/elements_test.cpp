#include "scene/elements.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace linkage {
namespace {

TEST(Elements, DefaultsShowALectureWithoutClutter) {
  const ElementSet set = ElementSet::defaults();
  for (const Element e : {Element::blocks, Element::pin, Element::pin_force, Element::gravity, Element::trail,
                          Element::com, Element::grid, Element::hud, Element::legend, Element::labels, Element::title})
    EXPECT_TRUE(set.has(e)) << name(e);
  EXPECT_FALSE(set.has(Element::velocity));
  EXPECT_FALSE(set.has(Element::axes));
}

TEST(Elements, EveryNameRoundTrips) {
  for (const ElementInfo& info : kElements) EXPECT_EQ(parse_element(info.name, "--show"), info.element);
}

TEST(Elements, ShowThenHideInAnyOrder) {
  ElementSet set = ElementSet::defaults();
  apply_show_hide(set, {"velocity,axes", "grid"}, {"trail", "grid"});
  EXPECT_TRUE(set.has(Element::velocity));
  EXPECT_TRUE(set.has(Element::axes));
  EXPECT_FALSE(set.has(Element::trail));
  EXPECT_FALSE(set.has(Element::grid));  // hidden wins
}

TEST(Elements, UnknownNameNamesFlagAndChoices) {
  ElementSet set;
  try {
    apply_show_hide(set, {}, {"pin,forces"});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    const std::string message = e.what();
    EXPECT_EQ(e.setting(), "hide") << message;  // the CLI says --hide, a lesson its key
    EXPECT_NE(message.find("'forces'"), std::string::npos) << message;
    EXPECT_NE(message.find("pin-force"), std::string::npos) << message;
  }
  EXPECT_THROW(apply_show_hide(set, {"blocks,"}, {}), Error);  // an empty name
  try {
    apply_show_hide(set, {"velocty"}, {});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.detail(), "'velocty' is not an element (did you mean 'velocity'?); valid: " + element_name_list());
  }
}

}  // namespace
}  // namespace linkage
