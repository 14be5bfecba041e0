// Small vibrations (formulations/linearization.cpp) against closed forms: the double
// pendulum of two uniform rods (the 2x2 eigenvalues, hanging and upright), the elastic
// pendulum (sqrt(k/m), sqrt(g/L) and a free turn; the damper's ratio c / (2 sqrt(k m))),
// and the bad inputs' one-line errors.
#include "formulations/linearization.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "core/error.hpp"
#include "model/mechanism_toml.hpp"
#include "support/closed_forms.hpp"
#include "support/test_support.hpp"

namespace linkage {
namespace {

using test::double_pendulum_w2;

Mechanism with(const std::string& name, const std::vector<std::string>& settings) {
  Mechanism m = load_mechanism(name);
  for (const std::string& s : settings) apply_setting(m, s, "test");
  return m;
}

TEST(Linearization, DoublePendulumHangingMatchesTheClosedForm) {
  const double l1 = 0.7, m1 = 1.3, l2 = 0.4, m2 = 0.55, g = 9.81;
  const sym::System system(with("double-pendulum", {"l1=0.7", "m1=1.3", "l2=0.4", "m2=0.55"}));
  const Linearization linear = linearize(system);
  ASSERT_EQ(linear.coordinates, (std::vector<std::string>{"1.theta", "2.theta"}));
  EXPECT_NEAR(linear.equilibrium[0], -std::numbers::pi / 2, 1e-13);
  EXPECT_NEAR(linear.equilibrium[1], -std::numbers::pi / 2, 1e-13);
  EXPECT_LE(linear.residual, 1e-12);
  EXPECT_NEAR(linear.M(0, 1), m2 * l1 * l2 / 2, 1e-14);
  EXPECT_NEAR(linear.K(0, 0), (m1 / 2 + m2) * g * l1, 1e-12);
  EXPECT_NEAR(linear.K(0, 1), 0, 1e-14);
  EXPECT_EQ(linear.C.cwiseAbs().maxCoeff(), 0);
  const ModalAnalysis modes = modal_analysis(linear);
  ASSERT_EQ(modes.modes.size(), 2U);
  EXPECT_TRUE(modes.stable);
  EXPECT_FALSE(modes.damped);
  const auto w2 = double_pendulum_w2(l1, m1, l2, m2, g, 1);
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    const Mode& mode = modes.modes[k];
    EXPECT_EQ(mode.kind, Mode::Kind::oscillation);
    EXPECT_NEAR(mode.omega * mode.omega / w2[k], 1, 1e-12);
    EXPECT_DOUBLE_EQ(mode.shape.cwiseAbs().maxCoeff(), 1.0);
    // K v = w^2 M v for the shape as given.
    EXPECT_LE((linear.K * mode.shape - mode.omega * mode.omega * linear.M * mode.shape).norm(),
              1e-12 * linear.K.norm());
  }
  // In phase, then against each other.
  EXPECT_GT(modes.modes[0].shape[0] * modes.modes[0].shape[1], 0);
  EXPECT_LT(modes.modes[1].shape[0] * modes.modes[1].shape[1], 0);
}

TEST(Linearization, UprightDoublePendulumIsUnstableWithTheClosedFormsGrowthRates) {
  const sym::System system(with("double-pendulum", {"1.theta=1.3", "2.theta=1.9"}));
  const Linearization linear = linearize(system);
  EXPECT_NEAR(linear.equilibrium[0], std::numbers::pi / 2, 1e-13);
  EXPECT_NEAR(linear.equilibrium[1], std::numbers::pi / 2, 1e-13);
  const ModalAnalysis modes = modal_analysis(linear);
  EXPECT_FALSE(modes.stable);
  const auto w2 = double_pendulum_w2(0.3, 0.2, 0.25, 0.15, 9.81, -1);
  ASSERT_EQ(modes.modes.size(), 2U);
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    EXPECT_EQ(modes.modes[k].kind, Mode::Kind::unstable);
    EXPECT_EQ(modes.modes[k].omega, 0);
    EXPECT_NEAR(-modes.modes[k].growth_rate * modes.modes[k].growth_rate / w2[k], 1, 1e-12);
  }
}

TEST(Linearization, ElasticPendulumBouncesAtSqrtKOverMAndSwingsAtSqrtGOverL) {
  const double m = 0.2, k = 20, l0 = 0.3, g = 9.81, c = 0.05;
  const sym::System system(load_mechanism("spring-pendulum"));
  const Linearization linear = linearize(system);
  const double L = l0 + m * g / k;  // the stretched spring
  ASSERT_EQ(linear.coordinates, (std::vector<std::string>{"1.x", "1.y", "1.theta"}));
  EXPECT_NEAR(linear.equilibrium[0], 0, 1e-13);
  EXPECT_NEAR(linear.equilibrium[1], -L, 1e-13);
  const ModalAnalysis modes = modal_analysis(linear);
  EXPECT_TRUE(modes.stable);
  EXPECT_TRUE(modes.damped);
  ASSERT_EQ(modes.modes.size(), 3U);
  EXPECT_EQ(modes.modes[0].kind, Mode::Kind::neutral);  // the disc turns freely
  EXPECT_DOUBLE_EQ(modes.modes[0].shape[2], 1.0);
  EXPECT_NEAR(modes.modes[1].omega / std::sqrt(g / L), 1, 1e-12);  // the swing, along x
  EXPECT_DOUBLE_EQ(modes.modes[1].shape[0], 1.0);
  EXPECT_NEAR(modes.modes[1].damping_ratio, 0, 1e-12);             // the damper acts along the spring only
  EXPECT_NEAR(modes.modes[2].omega / std::sqrt(k / m), 1, 1e-12);  // the bounce, along y
  EXPECT_DOUBLE_EQ(modes.modes[2].shape[1], 1.0);
  EXPECT_NEAR(modes.modes[2].damping_ratio / (c / (2 * std::sqrt(k * m))), 1, 1e-10);
}

// four-bar-spring.toml, the four-bar with a torsional spring at the rocker's ground pin O4,
// reduced by hand to its one coordinate, the crank angle: the loop closed by the two
// circles' intersection, the velocity and acceleration coefficients (theta2' = 1,
// theta2'' = 0) from the loop equation's derivatives, the potential's second derivative
// V'' and the effective inertia m_eff; omega^2 = V'' / m_eff where V' = 0.
struct FourBarByHand {
  double a = 0.1, ma = 0.1, b = 0.3, mb = 0.2, c = 0.25, mc = 0.15, d = 0.3, g = 9.81, k = 0.8, rest = 1.2;
  double th3 = 0, th4 = 0, w3 = 0, w4 = 0, al3 = 0, al4 = 0;

  // The loop at crank angle th2 on the branch of (th3, th4) near the guesses.
  void at(double th2, double guess3, double guess4) {
    const std::complex<double> A = a * std::polar(1.0, th2), O4(d, 0);
    const double l = std::abs(O4 - A), along = (b * b - c * c + l * l) / (2 * l), h = std::sqrt(b * b - along * along);
    const std::complex<double> u = (O4 - A) / l, foot = A + along * u;
    double best = 1e300;
    for (const double side : {1.0, -1.0}) {
      const std::complex<double> B = foot + side * h * std::complex<double>(0, 1) * u;
      const double t3 = std::arg(B - A), t4 = std::arg(B - O4);
      const double off = std::abs(std::remainder(t3 - guess3, 2 * std::numbers::pi)) +
                         std::abs(std::remainder(t4 - guess4, 2 * std::numbers::pi));
      if (off < best) {
        best = off;
        th3 = t3;
        th4 = t4;
      }
    }
    // a i e2 + b i e3 w3 - c i e4 w4 = 0, and its derivative for the accelerations.
    const std::complex<double> i(0, 1), e2 = std::polar(1.0, th2), e3 = std::polar(1.0, th3), e4 = std::polar(1.0, th4);
    const auto solve = [&](std::complex<double> rhs, double& x3, double& x4) {  // b i e3 x3 - c i e4 x4 = rhs
      const std::complex<double> p = b * i * e3, q = -c * i * e4;
      const double det = p.real() * q.imag() - p.imag() * q.real();
      x3 = (rhs.real() * q.imag() - rhs.imag() * q.real()) / det;
      x4 = (p.real() * rhs.imag() - p.imag() * rhs.real()) / det;
    };
    solve(-a * i * e2, w3, w4);
    solve(a * e2 + b * w3 * w3 * e3 - c * w4 * w4 * e4, al3, al4);
  }
  [[nodiscard]] double dV(double th2) const {  // gravity's and the spring's
    const double y2 = a / 2 * std::cos(th2), y3 = a * std::cos(th2) + b / 2 * std::cos(th3) * w3,
                 y4 = c / 2 * std::cos(th4) * w4;
    return g * (ma * y2 + mb * y3 + mc * y4) + k * (th4 - rest) * w4;
  }
  [[nodiscard]] double ddV(double th2) const {
    const double y2 = -a / 2 * std::sin(th2),
                 y3 = -a * std::sin(th2) + b / 2 * (std::cos(th3) * al3 - std::sin(th3) * w3 * w3),
                 y4 = c / 2 * (std::cos(th4) * al4 - std::sin(th4) * w4 * w4);
    return g * (ma * y2 + mb * y3 + mc * y4) + k * (w4 * w4 + (th4 - rest) * al4);
  }
  [[nodiscard]] double inertia(double th2) const {
    const std::complex<double> i(0, 1);
    const std::complex<double> v3 = a * i * std::polar(1.0, th2) + b / 2 * i * std::polar(1.0, th3) * w3;
    return ma * a * a / 4 + ma * a * a / 12 + mb * std::norm(v3) + mb * b * b / 12 * w3 * w3 +
           mc * c * c / 4 * w4 * w4 + mc * c * c / 12 * w4 * w4;
  }
};

TEST(Linearization, FourBarOnASpringMatchesTheEnergyMethodOnTheCrankAngle) {
  const sym::System system(load_mechanism("four-bar-spring"));  // k = 0.8 N m/rad at O4, slack at 1.2 rad
  const Linearization linear = linearize(system);
  ASSERT_EQ(linear.coordinates, (std::vector<std::string>{"2.theta"}));  // the file's independent coordinate
  const double th2 = linear.equilibrium[0];
  FourBarByHand hand;
  hand.at(th2, linear.equilibrium[1], linear.equilibrium[2]);
  EXPECT_NEAR(hand.th3, linear.equilibrium[1], 1e-12);
  EXPECT_NEAR(hand.th4, linear.equilibrium[2], 1e-12);
  EXPECT_NEAR(hand.dV(th2), 0, 1e-12);  // an equilibrium by the hand's potential too
  EXPECT_NEAR(linear.M(0, 0) / hand.inertia(th2), 1, 1e-12);
  EXPECT_NEAR(linear.K(0, 0) / hand.ddV(th2), 1, 1e-10);
  const ModalAnalysis modes = modal_analysis(linear);
  ASSERT_EQ(modes.modes.size(), 1U);
  ASSERT_EQ(modes.modes[0].kind, Mode::Kind::oscillation);
  EXPECT_NEAR(modes.modes[0].omega / std::sqrt(hand.ddV(th2) / hand.inertia(th2)), 1, 1e-10);
  // The shape in every tree coordinate: the coupler and rocker move by the velocity coefficients.
  EXPECT_NEAR(modes.modes[0].tree_shape[1], hand.w3, 1e-12);
  EXPECT_NEAR(modes.modes[0].tree_shape[2], hand.w4, 1e-12);
}

// coupled-pendulums.toml: three rods (m, L) from pins d apart, springs k at a below the
// pins, slack hanging: I th'' + (m g L / 2) th + k a^2 P th = 0 with I = m L^2 / 3 and P the
// path graph's Laplacian, eigenvalues 0, 1, 3 with shapes (1, 1, 1), (1, 0, -1), (1, -2, 1).
TEST(Linearization, CoupledPendulumsMatchThePathGraphsModes) {
  const double m = 0.2, L = 0.4, a = 0.25, k = 1.5, g = 9.81, I = m * L * L / 3;
  const sym::System system(load_mechanism("coupled-pendulums"));
  const ModalAnalysis modes = modal_analysis(linearize(system));
  ASSERT_EQ(modes.modes.size(), 3U);
  const std::array<double, 3> laplacian{0, 1, 3};
  const std::array<std::array<double, 3>, 3> shapes{{{1, 1, 1}, {1, 0, -1}, {-0.5, 1, -0.5}}};
  for (std::size_t n = 0; n < 3; ++n) {
    SCOPED_TRACE(n);
    EXPECT_NEAR(modes.modes[n].omega / std::sqrt((m * g * L / 2 + k * a * a * laplacian[n]) / I), 1, 1e-12);
    const Eigen::VectorXd& v = modes.modes[n].shape;
    const double sign = v.dot(Eigen::Vector3d(shapes[n][0], shapes[n][1], shapes[n][2])) > 0 ? 1 : -1;
    for (Eigen::Index i = 0; i < 3; ++i) EXPECT_NEAR(v[i], sign * shapes[n][static_cast<std::size_t>(i)], 1e-12);
  }
}

TEST(Linearization, AtInitialKeepsThePointAndReportsTheImbalance) {
  const sym::System system(load_mechanism("double-pendulum"));  // [initial]: -0.8, -1.2 rad
  LinearizeOptions options;
  options.at_initial = true;
  const Linearization linear = linearize(system, options);
  EXPECT_DOUBLE_EQ(linear.equilibrium[0], -0.8);
  EXPECT_DOUBLE_EQ(linear.equilibrium[1], -1.2);
  EXPECT_EQ(linear.newton_steps, 0);
  // The generalized forces of gravity there (absolute angles): (m1/2 + m2) g l1 cos(th1)
  // for th1, m2 g l2/2 cos(th2) for th2; the larger is left.
  const double g = 9.81;
  const double first = (0.2 / 2 + 0.15) * g * 0.3 * std::cos(-0.8), second = 0.25 * g * 0.25 / 2 * std::cos(-1.2);
  EXPECT_NEAR(linear.residual / std::max(first, second), 1, 1e-12);
}

TEST(Linearization, BadInputIsOneLine) {
  {  // a driver that moves with t: no fixed equilibrium
    const sym::System system(load_mechanism("engine"));
    const std::string message = test::input_error_of([&] { (void)linearize(system); });
    EXPECT_NE(message.find("moves with t"), std::string::npos) << message;
    EXPECT_NE(message.find("engine.toml:"), std::string::npos) << message;
  }
  {  // a locked driver takes the four-bar's one degree of freedom
    Mechanism m = load_mechanism("four-bar-driven");
    m.drivers.front().motion.text = "0.3";
    const sym::System system(m);
    const std::string message = test::input_error_of([&] { (void)linearize(system); });
    EXPECT_NE(message.find("no degree of freedom"), std::string::npos) << message;
  }
  {  // no gravity, no spring: every position is an equilibrium, every mode neutral
    const sym::System system(with("double-pendulum", {"g=0"}));
    const ModalAnalysis modes = modal_analysis(linearize(system));
    for (const Mode& mode : modes.modes) EXPECT_EQ(mode.kind, Mode::Kind::neutral);
  }
}

}  // namespace
}  // namespace linkage
