#include "eposp/drives/plant/motor_model.hpp"
#include "plant_test_motor.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace eposp::drives::plant {
namespace {

constexpr double kStep = 100e-6;

MotorModel run(PlantParameters plant, double voltage, double seconds) {
    MotorModel model(plant, kStep);
    for (int i = 0; i < static_cast<int>(std::lround(seconds / kStep)); ++i) {
        model.step(voltage);
    }
    return model;
}

TEST(MotorModel, SteadyStateSpeedIsVoltageLessResistiveDropOverBackEmf) {
    PlantParameters plant = test::free_motor();
    plant.load = {0, 2e-6, 2e-3};
    const MotorParameters& m = plant.motor;
    const double ke = m.back_emf_constant();
    const MotorModel model = run(plant, 12, 0.5);
    // k_t·I = b·ω + τ_c and U = R·I + k_e·ω
    const double b = plant.load.viscous_friction;
    const double tc = plant.load.coulomb_friction;
    const double speed = (12 - m.terminal_resistance * tc / m.torque_constant) /
                         (ke + m.terminal_resistance * b / m.torque_constant);
    EXPECT_NEAR(model.state().speed, speed, speed * 1e-9);
    EXPECT_NEAR(model.state().speed, (12 - m.terminal_resistance * model.state().current) / ke,
                speed * 1e-9);
}

TEST(MotorModel, LockedRotorCurrentRisesWithElectricalTimeConstant) {
    PlantParameters plant = test::free_motor();
    plant.load.coulomb_friction = 100; // holds the shaft
    const double r = plant.motor.terminal_resistance;
    const double tau = plant.motor.terminal_inductance / r;
    MotorModel model(plant, tau / 4);
    for (int i = 1; i <= 8; ++i) {
        model.step(10);
        EXPECT_NEAR(model.state().current, 10 / r * (1 - std::exp(-i / 4.0)), 1e-12) << i;
    }
    EXPECT_EQ(model.state().speed, 0);
}

TEST(MotorModel, StepTenTimesTheElectricalTimeConstantStaysStable) {
    // Explicit Euler would diverge here (dt > 2·L/R).
    PlantParameters plant = test::free_motor();
    plant.load.coulomb_friction = 100;
    const double r = plant.motor.terminal_resistance;
    MotorModel model(plant, 10 * plant.motor.terminal_inductance / r);
    model.step(10);
    EXPECT_NEAR(model.state().current, 10 / r * (1 - std::exp(-10.0)), 1e-12);
}

TEST(MotorModel, SpeedStepResponseMatchesSecondOrderClosedForm) {
    const PlantParameters plant = test::free_motor();
    const MotorParameters& m = plant.motor;
    const double ke = m.back_emf_constant();
    // L·J·s² + R·J·s + k_t·k_e = 0; ω(t) = ω∞·(1 − (s2·e^{s1 t} − s1·e^{s2 t})/(s2 − s1))
    const double a = m.terminal_inductance * m.rotor_inertia;
    const double b = m.terminal_resistance * m.rotor_inertia;
    const double c = m.torque_constant * ke;
    const double root = std::sqrt(b * b - 4 * a * c);
    const double s1 = (-b + root) / (2 * a);
    const double s2 = (-b - root) / (2 * a);
    const double final_speed = 12 / ke;
    MotorModel model(plant, kStep);
    for (int i = 1; i <= 400; ++i) {
        model.step(12);
        const double t = i * kStep;
        const double expected =
            final_speed * (1 - (s2 * std::exp(s1 * t) - s1 * std::exp(s2 * t)) / (s2 - s1));
        ASSERT_NEAR(model.state().speed, expected, final_speed * 0.005) << t;
    }
}

TEST(MotorModel, SpeedReachesSixtyThreePercentAfterMechanicalTimeConstant) {
    // With L/R negligible the motor is first order with τ_m = R·J/(k_t·k_e).
    PlantParameters plant = test::free_motor();
    plant.motor.terminal_inductance = 1e-7;
    const MotorParameters& m = plant.motor;
    const double ke = m.back_emf_constant();
    const double tau_m = m.terminal_resistance * m.rotor_inertia / (m.torque_constant * ke);
    constexpr double kFineStep = 1e-6;
    MotorModel model(plant, kFineStep);
    for (int i = 0; i < static_cast<int>(std::lround(tau_m / kFineStep)); ++i) {
        model.step(12);
    }
    EXPECT_NEAR(model.state().speed / (12 / ke), 1 - std::exp(-1.0), 0.002);
}

TEST(MotorModel, VoltageIsLimitedByPwmDuty) {
    const PlantParameters plant = test::free_motor();
    const MotorModel model = run(plant, 100, 0.2);
    EXPECT_NEAR(model.state().speed, 0.9 * 24 / plant.motor.back_emf_constant(), 1e-6);
}

TEST(MotorModel, UnpoweredShaftCoastsDownWithViscousFriction) {
    PlantParameters plant = test::free_motor();
    plant.load.viscous_friction = 1e-6;
    MotorModel model(plant, kStep);
    model.set_state({0, 100, 0});
    for (int i = 0; i < 10000; ++i) {
        model.step_unpowered();
    }
    const double expected = 100 * std::exp(-1e-6 * 1.0 / plant.motor.rotor_inertia);
    EXPECT_NEAR(model.state().speed, expected, expected * 0.01);
    EXPECT_EQ(model.state().current, 0);
}

TEST(MotorModel, CoulombFrictionStopsTheShaftWithoutReversing) {
    PlantParameters plant = test::free_motor();
    plant.load.coulomb_friction = 1e-3;
    MotorModel model(plant, kStep);
    model.set_state({0, 10, 0});
    for (int i = 0; i < 1000; ++i) {
        model.step_unpowered();
    }
    EXPECT_EQ(model.state().speed, 0);
    // ω0²·J/(2·τc): the angle the shaft coasts
    EXPECT_NEAR(model.state().angle, 100 * 1.05e-6 / 2e-3, 1e-4);
}

TEST(MotorModel, GearheadReflectsLoadAndDividesTheOutputAngle) {
    PlantParameters plant = test::free_motor();
    plant.load.inertia = 1e-3;
    plant.gearhead = {100, 0.8};
    MotorModel model(plant, kStep);
    EXPECT_NEAR(model.reflected_inertia(), 1.05e-6 + 1e-3 / 1e4, 1e-15);
    model.set_state({0, 0, 2 * std::numbers::pi * 100});
    EXPECT_NEAR(model.output_angle(), 2 * std::numbers::pi, 1e-12);
}

TEST(MotorModel, MeaninglessParametersAreRefused) {
    EXPECT_TRUE(validate(test::free_motor()).ok());
    const auto refused = [](auto change) {
        PlantParameters plant = test::free_motor();
        change(plant);
        return !validate(plant).ok();
    };
    EXPECT_TRUE(refused([](PlantParameters& p) { p.motor.terminal_inductance = 0; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.motor.terminal_resistance = -1; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.motor.speed_constant = 0; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.motor.rotor_inertia = 0; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.motor.pole_pairs = 0; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.load.coulomb_friction = -1e-3; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.gearhead.efficiency = 1.2; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.gearhead.ratio = 0; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.power_stage.max_duty = 0; }));
    EXPECT_TRUE(refused([](PlantParameters& p) { p.motor.torque_constant = std::nan(""); }));
}

} // namespace
} // namespace eposp::drives::plant
