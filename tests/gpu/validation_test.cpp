// The validation layer is really listening: a deliberate misuse must reach the log. Without this, a missing or
// silently disabled layer would make every other GPU test pass for the wrong reason.
#include <gtest/gtest.h>

#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::test {
namespace {

TEST(ValidationTest, MisuseIsReported) {
    vk::ValidationLog log;
    vk::ContextOptions options;
    options.validation = true;
    options.validationLog = &log;
    vk::Context context(options);
    ASSERT_TRUE(context.validationEnabled());
    vk::Buffer buffer(context, 64, vk::MemoryUsage::DeviceLocal);
    ASSERT_EQ(log.count(), 0u);
    // vkCmdFillBuffer requires a 4-byte aligned offset; 2 stays inside the buffer, so the driver is not at risk.
    context.submitAndWait([&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, buffer.handle(), 2, 4, 0); });
    EXPECT_GT(log.count(), 0u);
}

} // namespace
} // namespace simeco::test
