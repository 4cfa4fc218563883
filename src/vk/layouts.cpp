#include "vk/layouts.h"

#include <cstdint>

#include "vk/vk_error.h"

namespace simeco::vk {

UniqueDescriptorSetLayout createPushDescriptorSetLayout(VkDevice device,
                                                        std::span<const VkDescriptorSetLayoutBinding> bindings) {
    VkDescriptorSetLayoutCreateInfo setInfo{};
    setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = static_cast<std::uint32_t>(bindings.size());
    setInfo.pBindings = bindings.data();
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout));
    return UniqueDescriptorSetLayout(device, setLayout);
}

UniquePipelineLayout createPipelineLayout(VkDevice device, VkDescriptorSetLayout setLayout,
                                          std::optional<VkPushConstantRange> pushRange) {
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout;
    layoutInfo.pushConstantRangeCount = pushRange ? 1 : 0;
    layoutInfo.pPushConstantRanges = pushRange ? &*pushRange : nullptr;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
    return UniquePipelineLayout(device, layout);
}

} // namespace simeco::vk
