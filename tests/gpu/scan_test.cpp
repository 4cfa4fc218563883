// Exclusive prefix sums on the device against std::exclusive_scan, for both algorithms and sizes around every
// tile, subgroup and level boundary.
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "compute/shared/config.h"
#include "gpu/scan.h"
#include "gpu_fixture.h"
#include "vk/buffer.h"

namespace simeco::test {
namespace {

using gpu::ScanAlgorithm;

// Values below 16 keep the total of 10^7 elements far below 2^32.
std::vector<std::uint32_t> randomValues(std::size_t count, std::uint32_t seed) {
    std::mt19937 generator(seed);
    std::vector<std::uint32_t> values(count);
    for (std::uint32_t& v : values) {
        v = generator() & 15u;
    }
    return values;
}

// Reports the first mismatch only: a broken scan is wrong in millions of places.
::testing::AssertionResult sameScan(const std::vector<std::uint32_t>& expected,
                                    const std::vector<std::uint32_t>& actual) {
    if (expected.size() != actual.size()) {
        return ::testing::AssertionFailure() << "sizes differ: " << expected.size() << " vs " << actual.size();
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (expected[i] != actual[i]) {
            return ::testing::AssertionFailure() << "first difference at index " << i << " of " << expected.size()
                                                 << ": expected " << expected[i] << ", got " << actual[i];
        }
    }
    return ::testing::AssertionSuccess();
}

class ScanTest : public GpuTest, public ::testing::WithParamInterface<std::tuple<ScanAlgorithm, std::uint32_t>> {};

TEST_P(ScanTest, MatchesStdExclusiveScan) {
    auto [algorithm, count] = GetParam();
    std::vector<std::uint32_t> input = randomValues(count, 0x5eed + count);
    std::vector<std::uint32_t> expected(count);
    std::exclusive_scan(input.begin(), input.end(), expected.begin(), std::uint32_t{0});
    std::uint32_t expectedTotal = std::accumulate(input.begin(), input.end(), std::uint32_t{0});

    vk::Buffer in(context(), std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::Buffer out(context(), std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::uploadSpan<std::uint32_t>(context(), in, input);
    gpu::GpuScan scan(context());
    std::uint32_t total = scan.run(in, out, count, algorithm);

    EXPECT_TRUE(sameScan(expected, vk::downloadVector<std::uint32_t>(context(), out, count)));
    EXPECT_EQ(total, expectedTotal);
}

std::string scanName(const ::testing::TestParamInfo<ScanTest::ParamType>& info) {
    auto [algorithm, count] = info.param;
    std::string name(gpu::scanAlgorithmName(algorithm));
    std::erase(name, '-');
    return name + "_" + std::to_string(count);
}

// 31..33 and 255..257 straddle subgroup and workgroup widths, 4097 a tile, 65535..65537 a 16-tile boundary,
// 10^7 needs two levels of tile sums.
INSTANTIATE_TEST_SUITE_P(Sizes, ScanTest,
                         ::testing::Combine(::testing::Values(ScanAlgorithm::ReduceThenScan,
                                                              ScanAlgorithm::DecoupledLookBack),
                                            ::testing::Values(1u, 2u, 31u, 32u, 33u, 255u, 256u, 257u, 1000u, 4097u,
                                                              65535u, 65536u, 65537u, 100003u, 1000000u, 10000000u)),
                         scanName);

using ScanUsageTest = GpuTest;

TEST_F(ScanUsageTest, ReduceThenScanWorksInPlace) {
    const std::uint32_t count = 100003;
    std::vector<std::uint32_t> input = randomValues(count, 7);
    std::vector<std::uint32_t> expected(count);
    std::exclusive_scan(input.begin(), input.end(), expected.begin(), std::uint32_t{0});
    vk::Buffer data(context(), std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::uploadSpan<std::uint32_t>(context(), data, input);
    gpu::GpuScan scan(context());
    scan.run(data, data, count, ScanAlgorithm::ReduceThenScan);
    EXPECT_TRUE(sameScan(expected, vk::downloadVector<std::uint32_t>(context(), data, count)));
}

// With a single poll before the fallback, tiles regularly reduce stalled predecessors themselves.
TEST_F(ScanUsageTest, DecoupledLookBackFallbackGivesTheSameResult) {
    const std::uint32_t count = 1000003;
    std::vector<std::uint32_t> input = randomValues(count, 11);
    std::vector<std::uint32_t> expected(count);
    std::exclusive_scan(input.begin(), input.end(), expected.begin(), std::uint32_t{0});
    vk::Buffer in(context(), std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::Buffer out(context(), std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::uploadSpan<std::uint32_t>(context(), in, input);
    gpu::GpuScan scan(context());
    scan.setLookBackSpins(1);
    EXPECT_EQ(scan.run(in, out, count, ScanAlgorithm::DecoupledLookBack),
              std::accumulate(input.begin(), input.end(), std::uint32_t{0}));
    EXPECT_TRUE(sameScan(expected, vk::downloadVector<std::uint32_t>(context(), out, count)));
}

TEST_F(ScanUsageTest, EmptyScanHasZeroTotal) {
    vk::Buffer in(context(), 4, vk::MemoryUsage::DeviceLocal);
    vk::Buffer out(context(), 4, vk::MemoryUsage::DeviceLocal);
    gpu::GpuScan scan(context());
    EXPECT_EQ(scan.run(in, out, 0, ScanAlgorithm::ReduceThenScan), 0u);
    EXPECT_EQ(scan.run(in, out, 0, ScanAlgorithm::DecoupledLookBack), 0u);
}

TEST_F(ScanUsageTest, RecordingBeyondTheReservedSizeThrows) {
    vk::Buffer in(context(), 4 * shared::kScanTileSize * 2, vk::MemoryUsage::DeviceLocal);
    vk::Buffer out(context(), 4 * shared::kScanTileSize * 2, vk::MemoryUsage::DeviceLocal);
    gpu::GpuScan scan(context());
    scan.reserve(shared::kScanTileSize);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        EXPECT_THROW(scan.record(cmd, in, out, shared::kScanTileSize + 1), std::logic_error);
        EXPECT_THROW(scan.record(cmd, in, in, 16, ScanAlgorithm::DecoupledLookBack), std::invalid_argument);
    });
}

} // namespace
} // namespace simeco::test
