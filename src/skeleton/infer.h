// How a turtle regrows a skeleton: for every internode (internodes.h) the turns that take its parent's frame to
// its own direction, as the SimEco rotations rotr (about the reference axis r, the turtle's left) and rotu (about
// the parent's direction), and its length.
//
// Reference axes, as the thesis defines them: the first stem's r is the first stem's direction times its main child's
// (so that child turns by rotu 0), which the trunk's frame takes by a roll; a main child carries its parent's r
// turned with it by its rotr and rotu; a branch takes its parent's direction, the part of it at right angles to the
// branch, which a SimEco turtle reaches by a quarter roll after the branch's turn (lang/eco_compile.cpp). A cpfg
// turtle carries one frame into branches as into main stems.
//
// The turns and lengths are computed in the turtle's own float arithmetic (turtle/frame.h) from the frame and place
// the turtle will have, not from the skeleton's exact ones, so rounding does not add up along a stem: each
// internode aims from where the turtle stands at the skeleton point it must reach.
#pragma once

#include <vector>

#include "skeleton/internodes.h"

namespace simeco::skeleton {

// A turn as the turtle reads it: roll about the heading first, then pitch away from it (rotu then rotr in a
// SimEco successor, `/` then `&` in cpfg), in the unit the grammar writes (radians or degrees).
struct Turn {
    float pitch = 0.0f;
    float roll = 0.0f;
};

struct GrownChild {
    int internode = 0;
    Turn turn;
};

struct GrownOrgan {
    int organ = 0; // of the plant
    Turn turn;
};

struct GrownInternode {
    float length = 0.0f; // what the turtle moves, aiming at the skeleton point
    float width = 0.0f;
    float rollAfter = 0.0f; // the trunk's: the roll that brings its left to the first stem's reference axis
    std::vector<GrownChild> children; // the main child first
    std::vector<GrownOrgan> organs;
};

// Which turtle regrows the plant: a SimEco script's (turns in radians, branches take their parent's direction as
// their reference axis) or a cpfg L-system's (turns in degrees, one frame carried into branches).
enum class Dialect { SimEco, Cpfg };

struct Regrowth {
    InternodeTree tree;
    std::vector<GrownInternode> internodes; // by internode
    std::vector<GrownChild> roots;          // from the plant's base, in its upright frame; the trunk first
    std::vector<GrownOrgan> baseOrgans;
    Dialect dialect = Dialect::SimEco;
};

// The turns and lengths that regrow `plant` (checked) from its base, the turtle starting upright there (heading +y,
// left -x), as simeco draws a grammar's plant at the origin of its own space.
Regrowth regrowth(const Plant& plant, Dialect dialect);

} // namespace simeco::skeleton
