#include "app/error_report.h"

#include <cstdio>
#include <exception>
#include <new>

#include "ir/source_loc.h"
#include "vk/vk_error.h"

namespace simeco::app {

int runReportingErrors(const std::function<void()>& body) {
    try {
        body();
        return kExitOk;
    } catch (const ir::InputError& e) {
        std::fprintf(stderr, "%s\n", e.formatted().c_str());
        return kExitBadInput;
    } catch (const CommandLineError& e) {
        std::fprintf(stderr, "simeco: error: %s\n", e.what());
        return kExitBadInput;
    } catch (const ir::LimitError& e) {
        std::fprintf(stderr, "simeco: error: %s\n", e.what());
        return kExitRuntime;
    } catch (const vk::VulkanError& e) {
        std::fprintf(stderr, "simeco: error: %s\n", e.what());
        return kExitRuntime;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "simeco: error: out of host memory\n");
        return kExitRuntime;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "simeco: error: %s\n", e.what());
        return kExitRuntime;
    }
}

} // namespace simeco::app
