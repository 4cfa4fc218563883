// The particle state that travels with each module of the derivation stream, shared by C++ and GLSL.
//
// Every module is a particle of the growth simulation. Its state is kParticleStateFloats floats per module, in
// an array beside the stream's symbols and parameters. A derivation step moves it with the modules. A copied
// module keeps its own state. Every module of a successor starts with the state of the module it replaces
// (the first module of the predecessor), and so do the modules that decomposition and the homomorphism make.
// The growth rules then decide what a new organ keeps of it. The derivation only moves the state; until growth
// fills it, the axiom's modules start at zero.
#ifndef SIMECO_SHARED_PARTICLE_LAYOUT_H
#define SIMECO_SHARED_PARTICLE_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

// Two vec4 per module: the kernels move a module's state as two vector loads and stores.
SIMECO_CONST kParticleStateFloats = 8u;
SIMECO_CONST kParticleStateVec4s = kParticleStateFloats / 4u;
// The slots, as the growth simulation uses them.
SIMECO_CONST kParticleAge = 0u;        // time since the particle was born
SIMECO_CONST kParticleElongation = 1u; // its length so far
SIMECO_CONST kParticleBroadening = 2u; // its width so far
SIMECO_CONST kParticleNoise = 3u;      // the phase of its noise
SIMECO_CONST kParticleBendX = 4u;      // x, y, z: the direction its tropisms turned it to
SIMECO_CONST kParticleBendY = 5u;
SIMECO_CONST kParticleBendZ = 6u;
SIMECO_CONST kParticleLight = 7u;      // the light it received last

#ifdef __cplusplus
struct ParticleState {
    float value[kParticleStateFloats] = {};
    bool operator==(const ParticleState&) const = default;
};
#endif
SIMECO_SHARED_END

#endif
