// The particle state that travels with each module of the derivation stream, shared by C++ and GLSL.
//
// Every module is a particle of the growth simulation. Its state is kParticleStateFloats floats per module, in
// an array beside the stream's symbols and parameters. A derivation step moves it with the modules. A copied
// module keeps its own state. Every module of a successor starts with the state of the module it replaces
// (the first module of the predecessor), and so do the modules that decomposition and the homomorphism make.
// The growth tick (compute/grow/tick.comp) then decides which of them continues the particle and which are
// born: see compute/shared/growth_layout.h. Until a tick runs, the axiom's modules start at zero.
#ifndef SIMECO_SHARED_PARTICLE_LAYOUT_H
#define SIMECO_SHARED_PARTICLE_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

// Four vec4 per module: the kernels move a module's state as four vector loads and stores.
SIMECO_CONST kParticleStateFloats = 16u;
SIMECO_CONST kParticleStateVec4s = kParticleStateFloats / 4u;
// The slots, as the growth simulation uses them.
SIMECO_CONST kParticleAge = 0u;        // seconds since the particle was born
SIMECO_CONST kParticleElongation = 1u; // its length so far (a leaf's growth, a flower's or fruit's size)
SIMECO_CONST kParticleBroadening = 2u; // its width so far
SIMECO_CONST kParticleShade = 3u;      // seconds it has stood in deep shade without a break (growth_layout.h)
SIMECO_CONST kParticlePitch = 4u;      // radians its segment tilts away from its parent's heading
SIMECO_CONST kParticleRoll = 5u;       // radians about the parent's heading that tilt goes toward
SIMECO_CONST kParticleStageAge = 6u;   // seconds in its current stage
SIMECO_CONST kParticleLight = 7u;      // the light it received last (the light grid's; 0 until one runs)
SIMECO_CONST kParticleStage = 8u;      // the stage it was in at the last tick
SIMECO_CONST kParticleId = 9u;         // its identity, a uint's bits (0: not yet born)
SIMECO_CONST kParticleLightDirection = 10u; // the direction of most light: octahedral x, y as GLSL's packSnorm2x16
SIMECO_CONST kParticleClass = 11u;     // the class of the module it was born as (growth_layout.h), a uint's bits
SIMECO_CONST kParticleSpace = 12u;     // the room it has to grow, from the light grid (light_layout.h): 1 free
// Slots 13 to 15 are unused (zero).

#ifdef __cplusplus
struct ParticleState {
    float value[kParticleStateFloats] = {};
    bool operator==(const ParticleState&) const = default;
};
#endif
SIMECO_SHARED_END

#endif
