// Descriptor set and pipeline layouts for push descriptors, the one binding model simeco's pipelines use.
#pragma once

#include <optional>
#include <span>

#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace simeco::vk {

// A set layout whose descriptors are pushed (VK_KHR_push_descriptor) rather than allocated.
UniqueDescriptorSetLayout createPushDescriptorSetLayout(VkDevice device,
                                                        std::span<const VkDescriptorSetLayoutBinding> bindings);

// A pipeline layout with that one set and at most one push-constant range.
UniquePipelineLayout createPipelineLayout(VkDevice device, VkDescriptorSetLayout setLayout,
                                          std::optional<VkPushConstantRange> pushRange);

} // namespace simeco::vk
