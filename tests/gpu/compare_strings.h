// Comparing a derived string with the CPU reference's: the same modules, parameters within float rounding.
#pragma once

#include <string>

#include "cpu/derive.h"
#include "stream/device_modules.h"
#include "vk/context.h"

namespace simeco::test {

// Empty when `got` equals `want`; else the first differing module with what precedes it, and any difference
// in module count, plant segments or steps.
std::string firstDifference(const stream::DeriveResult& want, const stream::DeriveResult& got,
                            const ir::Alphabet& alphabet);

// A string left on the device, read back as derive() returns it (its particle state too, where it carries it).
stream::DeriveResult readModules(const vk::Context& context, const stream::DeviceModules& modules, int steps);

} // namespace simeco::test
