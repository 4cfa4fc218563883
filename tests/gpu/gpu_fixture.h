// A test fixture sharing one validated Vulkan context per test process and failing any test during which the
// validation layer reported something.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "vk/context.h"

namespace simeco::test {

class GpuTest : public ::testing::Test {
protected:
    static void SetUpTestSuite();
    static void TearDownTestSuite();
    void SetUp() override;
    void TearDown() override;

    static vk::Context& context() { return *context_; }

private:
    static vk::ValidationLog log_;  // outlives the context, so messages from its destruction are seen
    static std::unique_ptr<vk::Context> context_;
    static std::string setupError_;
    std::size_t messagesBefore_ = 0;
};

} // namespace simeco::test
