// Dimensional analysis of the definitions: each gets the unit its parameters give it.
#include "symbolic/units.hpp"

#include <gtest/gtest.h>

namespace linkage::sym {
namespace {

struct Table {
  SymbolTable table;
  GiNaC::symbol add(const std::string& name, const std::string& unit) {
    return table.add({GiNaC::symbol(name), Role::parameter, name, name, name, name, unit, ""}).symbol;
  }
};

TEST(Units, ParsesProductsQuotientsAndDerivedUnits) {
  const auto same = [](const std::string& a, const std::string& b) {
    return (*parse_unit(a) / *parse_unit(b)).normal().is_equal(1);
  };
  EXPECT_TRUE(same("N", "kg m/s^2"));
  EXPECT_TRUE(same("N s/m", "kg/s"));
  EXPECT_TRUE(same("J", "N m"));
  EXPECT_TRUE(same("rad", ""));
  EXPECT_TRUE(same("1/s", "Hz"));
  EXPECT_TRUE(same("kg m^2", "kg*m^2"));
  EXPECT_TRUE(same("m/(s s)", "m/s^2"));
  EXPECT_FALSE(parse_unit("furlong").has_value());
  EXPECT_FALSE(parse_unit("m^x").has_value());
  EXPECT_FALSE(parse_unit("m/s/s").has_value());
}

TEST(Units, DefinitionsTakeTheirParametersUnits) {
  Table t;
  const GiNaC::symbol L = t.add("L", "m"), b = t.add("b", "m"), m = t.add("m", "kg"), k = t.add("k", "N/m"),
                      c = t.add("c", "N s/m"), g = t.add("g", "m/s^2"), n = t.add("n", "");
  EXPECT_EQ(unit_of(L / 2 - b, t.table), "m");
  EXPECT_EQ(unit_of(m * (L * L + b * b) / 12, t.table), "kg m^2");
  EXPECT_EQ(unit_of(k / m, t.table), "1/s^2");
  EXPECT_EQ(unit_of(c / m, t.table), "1/s");
  EXPECT_EQ(unit_of(m * g * L, t.table), "kg m^2/s^2");
  EXPECT_EQ(unit_of(m * g / (L * k), t.table), "");  // a pure number
  EXPECT_EQ(unit_of(n * L, t.table), "m");
  EXPECT_EQ(unit_of(L / (m * c), t.table), "m s/kg^2");
  EXPECT_FALSE(unit_of(L + m, t.table).has_value());  // terms that disagree
  EXPECT_FALSE(unit_of(GiNaC::sqrt(L), t.table).has_value());
  EXPECT_FALSE(unit_of(GiNaC::ex(0), t.table).has_value());
}

}  // namespace
}  // namespace linkage::sym
