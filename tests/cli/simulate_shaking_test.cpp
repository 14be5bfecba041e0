// Issue 25, Deliver 4: the shaking force and moment, what the moving bodies exert on the
// ground, against Newton's second law for the moving bodies together. Forces between
// moving bodies cancel in pairs, so with F_ext the loads from outside that are not the
// ground's (gravity, applied forces and torques):
//   sum_b m_b a_b = F_ext - F_shaking,
//   sum_b (r_b x m_b a_b + I_b alpha_b) = M_ext,O - M_shaking,O,
// each side from its own columns: the bodies' accelerations, the loads' values by hand,
// and the shaking columns from the joint forces and driver multipliers.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace linkage::test {
namespace {

constexpr double kG = 9.81;

struct BodyMass {
  std::string name;
  double m, I;
};

/// The external loads on the moving bodies other than gravity, from a row: force x, y and
/// moment about the origin.
using Applied = std::function<std::array<double, 3>(const Table&, const std::vector<double>&)>;

struct Case {
  std::string file;
  std::vector<BodyMass> bodies;
  Applied applied;
  std::string extra_columns = {};  // what `applied` reads besides the bodies' positions
};

std::array<double, 3> none(const Table&, const std::vector<double>&) { return {0, 0, 0}; }

double rod(double m, double l) { return m * l * l / 12; }

void check(const Case& c) {
  std::string columns = "t,shaking_force_x,shaking_force_y,shaking_moment";
  for (const BodyMass& b : c.bodies)
    for (const char* k : {".x", ".y", ".x_ddot", ".y_ddot", ".theta_ddot"}) columns += "," + b.name + k;
  columns += c.extra_columns;
  for (int case_id : {1, 2, 3}) {
    const RunResult r =
        run_linkage({"simulate", "--mechanism", test_mechanism(c.file), "--case", std::to_string(case_id), "--rtol",
                     "1e-12", "--atol", "1e-12", "--duration", "1.5", "--every", "0.05", "--columns", columns});
    ASSERT_EQ(r.exit_code, 0) << c.file << " Case " << case_id << ": " << r.err;
    const Table table = parse_csv(r.out);
    ASSERT_EQ(table.rows.size(), 31U);
    double largest = 0;
    for (const std::vector<double>& row : table.rows) {
      const auto at = [&](const std::string& name) { return row[table.index(name)]; };
      const std::array<double, 3> applied = c.applied(table, row);
      double fx = applied[0], fy = applied[1], moment = applied[2], scale = 0;
      for (const BodyMass& b : c.bodies) {
        const double x = at(b.name + ".x"), y = at(b.name + ".y");
        const double ax = at(b.name + ".x_ddot"), ay = at(b.name + ".y_ddot"), alpha = at(b.name + ".theta_ddot");
        fx -= b.m * ax;
        fy += -b.m * kG - b.m * ay;
        moment += x * (-b.m * kG) - (b.m * (x * ay - y * ax) + b.I * alpha);
        scale += b.m * (kG + std::fabs(ax) + std::fabs(ay)) * (1 + std::hypot(x, y)) + b.I * std::fabs(alpha);
      }
      const std::string what = c.file + " Case " + std::to_string(case_id) + " t " + std::to_string(row[0]);
      EXPECT_NEAR(at("shaking_force_x"), fx, 1e-9 * scale) << what;
      EXPECT_NEAR(at("shaking_force_y"), fy, 1e-9 * scale) << what;
      EXPECT_NEAR(at("shaking_moment"), moment, 1e-9 * scale) << what;
      largest = std::max({largest, std::fabs(fx), std::fabs(moment)});
    }
    EXPECT_GT(largest, 0.1) << c.file << " Case " << case_id;
  }
}

// Driven at its crank (the motor's reaction torque on the frame), a damper at the moving pin A.
TEST(SimulateShaking, TheDrivenFourBarShakesItsFrameAsNewtonSays) {
  check({"driven-four-bar.toml",
         {{"2", 0.1, rod(0.1, 0.1)}, {"3", 0.2, rod(0.2, 0.3)}, {"4", 0.15, rod(0.15, 0.25)}},
         none});
}

// offset-slider-crank.toml's bodies: rods r = 0.1, l = 0.35 of 0.4 kg, a 0.08 x 0.05 piston of 0.6 kg.
std::vector<BodyMass> slider_crank_bodies() {
  return {{"crank", 0.4, rod(0.4, 0.1)},
          {"rod", 0.4, rod(0.4, 0.35)},
          {"piston", 0.6, 0.6 * (0.08 * 0.08 + 0.05 * 0.05) / 12}};
}

// A ground pin, a ground slider (its force and moment) and the motor at the crank.
TEST(SimulateShaking, TheOffsetSliderCrankShakesItsFrameAsNewtonSays) {
  check({"offset-slider-crank.toml", slider_crank_bodies(), none});
}

// The same with its ground joints written ground second: the ground takes -F and -M.
TEST(SimulateShaking, GroundSecondInAJointShakesTheFrameTheSame) {
  check({"offset-slider-crank-reversed.toml", slider_crank_bodies(), none});
}

// A damper in the ground pin: its torque on the rod is the ground's, so the frame takes -it.
TEST(SimulateShaking, AGroundPinsDamperTorqueIsInTheShakingMoment) {
  check({"damped-pendulum-pin.toml", {{"pend", 0.5, rod(0.5, 0.6)}}, none});
}

// state-loads-cart.toml: a spring from the ground's A, a ground slider, applied loads (on
// the cart at C = its centre: (-0.1 s', 0), s = cart.x; on the rod at its tip T:
// -b (rod.x', rod.y'); on the rod: the torque -0.2 s th').
TEST(SimulateShaking, AGroundSpringAndAppliedLoadsEnterAsNewtonSays) {
  const Applied loads = [](const Table& table, const std::vector<double>& row) -> std::array<double, 3> {
    const auto at = [&](const std::string& name) { return row[table.index(name)]; };
    const double b = 0.3, l = 0.5;
    const double s = at("cart.x"), s_dot = at("cart.x_dot"), th = at("rod.theta"), th_dot = at("rod.theta_dot");
    const double cart_fx = -0.1 * s_dot, cart_y = at("cart.y");
    const double tip_x = at("rod.x") + l / 2 * std::cos(th), tip_y = at("rod.y") + l / 2 * std::sin(th);
    const double rod_fx = -b * at("rod.x_dot"), rod_fy = -b * at("rod.y_dot");
    const double torque = -0.2 * s * th_dot;
    return {cart_fx + rod_fx, rod_fy, -cart_y * cart_fx + tip_x * rod_fy - tip_y * rod_fx + torque};
  };
  check({"state-loads-cart.toml",
         {{"cart", 1.0, 1.0 * (0.3 * 0.3 + 0.1 * 0.1) / 12}, {"rod", 0.4, rod(0.4, 0.5)}},
         loads,
         ",cart.x_dot,rod.theta,rod.theta_dot,rod.x_dot,rod.y_dot"});
}

}  // namespace
}  // namespace linkage::test
