// The reference turtle: interprets the module stream left to right with a plain stack, as cpfg does. The
// turtle kernels (turtle/turtle_gpu.h) compute the same organs in parallel and are tested against it.
#pragma once

#include <cstdint>
#include <vector>

#include "stream/module_string.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_settings.h"

namespace simeco::turtle {

// `species[p % species.size()]` holds plant p's settings; `commands` tells each module's kTurtle* command.
// `string` is what the turtle reads: the derived string after the homomorphism.
Interpretation interpretCpu(const stream::ModuleString& string, const TurtleCommands& commands,
                            const std::vector<TurtleSettings>& species, const FieldOptions& field = {});

// The box an organ takes, as the turtle kernels bound it (compute/turtle/organ_bounds.glsl): infinite for an organ
// whose values are not all finite.
Bounds organBounds(const shared::OrganInstance& o);

// Query modules ?P, ?H, ?L, ?U get the turtle's position or vector where they stand (in the plant's own
// space), as cpfg fills them after interpreting the string: two parameters get x and y, three x, y and z.
void fillQueries(stream::ModuleString& string, const TurtleCommands& commands,
                 const std::vector<TurtleSettings>& species);

// Where each module the turtle takes for cpfg's `?E` stands: the turtle's position after it, in its plant's own
// space (the light grid answers it: compute/shared/light_layout.h).
struct EnvironmentQuery {
    size_t module = 0;
    uint32_t plant = 0;
    glm::vec3 position{0.0f};
};
std::vector<EnvironmentQuery> environmentQueries(const stream::ModuleString& string, const TurtleCommands& commands,
                                                 const std::vector<TurtleSettings>& species);

} // namespace simeco::turtle
