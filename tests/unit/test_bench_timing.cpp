// The benchmark's measurements taken in turns: the rounds' order, warm-up rounds left out, and a measurement
// that fails leaving the others running.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bench/timing.h"

namespace simeco::bench {
namespace {

// A measurement that appends `name` to `log` and measures first, first + 1, ...
Measurement counter(std::string& log, char name, double first) {
    Measurement m;
    m.run = [&log, name, next = first]() mutable {
        log += name;
        return next++;
    };
    return m;
}

TEST(RunInTurns, EachRoundRunsEveryMeasurementOnceInOrder) {
    std::string log;
    Measurement cpu = counter(log, 'c', 1), gpu = counter(log, 'g', 101);
    runInTurns(2, 3, {&cpu, &gpu});
    EXPECT_EQ(log, "cgcgcgcgcg");
    // The two warm-up rounds' values are not samples.
    EXPECT_EQ(cpu.samples, (std::vector<double>{3, 4, 5}));
    EXPECT_EQ(gpu.samples, (std::vector<double>{103, 104, 105}));
    EXPECT_TRUE(cpu.error.empty());
    EXPECT_TRUE(gpu.error.empty());
}

TEST(RunInTurns, AMeasurementThatThrowsStopsAndKeepsItsError) {
    std::string log;
    Measurement failing = counter(log, 'f', 1), other = counter(log, 'o', 1);
    failing.run = [counted = failing.run]() {
        double value = counted();
        if (value == 3) throw std::runtime_error("out of device memory");
        return value;
    };
    runInTurns(1, 4, {&failing, &other});
    EXPECT_EQ(log, "fofofooo");
    EXPECT_EQ(failing.error, "out of device memory");
    EXPECT_EQ(failing.samples, (std::vector<double>{2})); // the warm-up's value is not one
    EXPECT_EQ(other.samples, (std::vector<double>{2, 3, 4, 5}));
}

} // namespace
} // namespace simeco::bench
