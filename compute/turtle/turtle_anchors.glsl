// A module's anchor and state from the two-level composition: chunk_steps.comp left every module's step and
// pointer relative to a target (or its anchor) in `chunkSteps`/`chunkPointers`; jump_steps.comp left the
// targets' steps and pointers relative to their anchors in `jumpedSteps`/`jumpedPointers`. Needs
// turtle/turtle_modules.glsl and these buffers: marks, targets, chunkSteps, chunkPointers, jumpedSteps,
// jumpedPointers, states (the non-linear modules' states, where resolved), plantOfModule.

bool isTarget(uint j) { return j != kNoModule && (marks[j] & kMarkNonlinear) == 0u; }

// The nearest non-linear ancestor of module i (i itself when non-linear), or kNoModule for the plant's root.
uint anchorOf(uint i) {
    if ((marks[i] & kMarkNonlinear) != 0u) return i;
    if (targets[i] != 0u) return jumpedPointers[i];
    uint j = chunkPointers[i];
    return isTarget(j) ? jumpedPointers[j] : j;
}

TurtleState anchorState(uint anchor, uint module) {
    if (anchor != kNoModule) return states[anchor];
    return initialState(speciesTable[speciesOf(plantOfModule[module])]);
}

// The state after linear module i, once every non-linear module on its path is resolved.
TurtleState linearState(uint i) {
    if (targets[i] != 0u) return applyStep(anchorState(jumpedPointers[i], i), jumpedSteps[i]);
    uint j = chunkPointers[i];
    if (!isTarget(j)) return applyStep(anchorState(j, i), chunkSteps[i]);
    TurtleState target = applyStep(anchorState(jumpedPointers[j], i), jumpedSteps[j]);
    return applyStep(target, chunkSteps[i]);
}
