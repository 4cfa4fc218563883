#include "gpu_fixture.h"

#include <cstdlib>
#include <vector>

namespace simeco::test {

vk::ValidationLog GpuTest::log_;
std::unique_ptr<vk::Context> GpuTest::context_;
std::string GpuTest::setupError_;

namespace {

// Kernels the tests generate are cached in the build tree, not in the user's cache.
const bool kKernelCacheInBuildTree = [] {
    ::setenv("SIMECO_KERNEL_CACHE", SIMECO_TEST_KERNEL_CACHE, 0);
    return true;
}();

std::string listMessages(const vk::ValidationLog& log, std::size_t from) {
    std::vector<std::string> messages = log.messages();
    std::string text;
    for (std::size_t i = from; i < messages.size(); ++i) {
        text += "\n  " + messages[i];
    }
    return text;
}

} // namespace

void GpuTest::SetUpTestSuite() {
    if (context_) {
        return;
    }
    // Validation is forced on, not only taken from SIMECO_VALIDATION, so running the binary by hand checks too.
    vk::ContextOptions options;
    options.validation = true;
    options.validationLog = &log_;
    try {
        context_ = std::make_unique<vk::Context>(options);
    } catch (const std::exception& e) {
        setupError_ = e.what();
    }
}

void GpuTest::TearDownTestSuite() {
    if (!context_) {
        return;
    }
    // Destroying the device and instance reports leaked objects, which count as failures too.
    std::size_t before = log_.count();
    context_.reset();
    EXPECT_EQ(log_.count(), before) << "validation messages while destroying the context:" << listMessages(log_, before);
}

void GpuTest::SetUp() {
    ASSERT_TRUE(context_) << "could not create a Vulkan context with validation: " << setupError_
                          << "\n(needs a Vulkan driver, e.g. mesa-vulkan-drivers, and vulkan-validationlayers)";
    ASSERT_TRUE(context_->validationEnabled()) << "VK_LAYER_KHRONOS_validation is not active";
    ASSERT_EQ(log_.count(), 0u) << "validation messages before this test (context creation or an earlier test):"
                                << listMessages(log_, 0);
    messagesBefore_ = log_.count();
}

void GpuTest::TearDown() {
    if (!context_) {
        return;
    }
    EXPECT_EQ(log_.count(), messagesBefore_) << "validation messages during the test:"
                                             << listMessages(log_, messagesBefore_);
}

} // namespace simeco::test
