// The work lists of pointer jumping (compute/shared/turtle_state_layout.h kJumpListHeader). A chunk pass appends
// each target once; a round walks the list it is given and hands on to the next round the items whose answer may
// still change, so that rounds past the longest chain walk nothing. An item whose input is final is copied into
// the round's output and dropped: from then on both buffers of the ping-pong hold its answer, which the later
// rounds read. The including kernel defines JUMP_LIST_IN_BINDING (none for a pass that only appends) and
// JUMP_LIST_OUT_BINDING.
#ifdef JUMP_LIST_IN_BINDING
layout(set = 0, binding = JUMP_LIST_IN_BINDING, std430) readonly buffer ListIn {
    uint inHeader[kJumpListHeader];
    uint inItems[];
};

// The item invocation k walks, or kNoModule past the list's end.
uint listItem(uint k) { return k < inHeader[kJumpListCount] ? inItems[k] : kNoModule; }
#endif

layout(set = 0, binding = JUMP_LIST_OUT_BINDING, std430) buffer ListOut {
    uint outHeader[kJumpListHeader];
    uint outItems[];
};

void passOn(uint module) { outItems[atomicAdd(outHeader[kJumpListCount], 1u)] = module; }

#ifndef JUMP_LIST_IN_BINDING
// For the chunk passes, which start the list: module q becomes a target (its flag in `targets` set), appended
// once however many modules point at it.
void markTarget(uint q) {
    if (targets[q] == 0u && atomicExchange(targets[q], 1u) == 0u) passOn(q);
}
#endif
