// The turtle's status words (compute/shared/turtle_state_layout.h), read for the modules a pass interprets:
// pc.count only bounds them. The including kernel defines TURTLE_STATUS_BINDING, the binding after its others.
layout(set = 0, binding = TURTLE_STATUS_BINDING, std430) readonly buffer Status { uint status[]; };

// At most the bound: a recorded derivation that stopped leaves a table the turtle must not trust.
uint moduleCount() { return min(status[kTurtleStatusModules], pc.count); }
