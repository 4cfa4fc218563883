// Reading modules as the turtle sees them: their commands (turtle/turtle_commands.cpp's commandAt, from the
// same tables), parameters, plants and species, and each command's step or absolute effect on the state
// (turtle/turtle_cpu.cpp's apply). Needs shared/turtle_layout.h, shared/turtle_state_layout.h,
// turtle/turtle_math.glsl, push constants `pc` (TurtlePush) and these buffers declared before it:
// symbols (uint: symbol | count << 24), params (float, pc.stride per module), plantStarts (uint, plants + 1),
// commandTable (uint: plain, afterAt, afterQuery, pairPrefix rows of pc.symbols, then kPairPrefixes rows of
// pairs) and speciesTable (TurtleSpecies).

const float kDegrees = 3.14159265358979 / 180.0;

uint symbolAt(uint i) { return symbols[i] & 0xFFFFFFu; }
uint paramCountAt(uint i) { return symbols[i] >> 24u; }
bool hasParam(uint i) { return paramCountAt(i) > 0u; }
float paramAt(uint i, uint k, float otherwise) { return paramCountAt(i) > k ? params[i * pc.stride + k] : otherwise; }

uint plainCommand(uint sym) { return commandTable[sym]; }
uint afterAtCommand(uint sym) { return commandTable[pc.symbols + sym]; }
uint afterQueryCommand(uint sym) { return commandTable[2u * pc.symbols + sym]; }
uint pairPrefixOf(uint sym) { return commandTable[3u * pc.symbols + sym]; }
uint pairCommand(uint prefix, uint sym) { return commandTable[(4u + prefix) * pc.symbols + sym]; }

// The plant whose modules contain i: the last plant starting at or before it.
uint plantOf(uint i) {
    uint lo = 0u, hi = pc.plants; // plantStarts[lo] <= i < plantStarts[hi]
    while (hi - lo > 1u) {
        uint mid = (lo + hi) / 2u;
        if (plantStarts[mid] <= i) lo = mid;
        else hi = mid;
    }
    return lo;
}

uint speciesOf(uint plant) { return plant % pc.species; }

// A generalized cylinder's mesh (cylinder_mesh.glsl): its rings' sides, and the strips of the stretch that ends
// at control point i, as many as `@Gc(n)` asks (n truncated, at least one), four without n.
uint cylinderSides(TurtleSpecies sp) { return (sp.cylinders >> kCylinderSidesShift) & kMostCylinderSides; }
uint cylinderRings(uint i) {
    if (!hasParam(i)) return 4u;
    float n = paramAt(i, 0u, 1.0);
    if (!(n >= 1.0)) return 1u;
    return uint(min(trunc(n), float(kTubeMaxSegments)));
}

uint commandAt(uint i, uint begin, uint end) {
    uint sym = symbolAt(i);
    if (sym >= pc.symbols) return kTurtleNone;
    if (i == begin) return plainCommand(sym);
    uint previous = symbolAt(i - 1u);
    if (previous == pc.atSymbol) {
        uint prefix = pairPrefixOf(sym);
        if (prefix != kPairNone && paramCountAt(i) == 0u && i + 1u < end && symbolAt(i + 1u) < pc.symbols &&
            pairCommand(prefix, symbolAt(i + 1u)) != kTurtleNone)
            return kTurtleNone; // the first letter of a two-letter command
        return afterAtCommand(sym);
    }
    if (i >= begin + 2u && symbolAt(i - 2u) == pc.atSymbol && previous < pc.symbols &&
        pairPrefixOf(previous) != kPairNone && paramCountAt(i - 1u) == 0u) {
        uint pair = pairCommand(pairPrefixOf(previous), sym);
        if (pair != kTurtleNone) return pair;
    }
    if (previous == pc.tildeSymbol) return kTurtleSurface;
    if (previous == pc.querySymbol && paramCountAt(i - 1u) == 0u) return afterQueryCommand(sym); // else a call
    return plainCommand(sym);
}

// A `~` surface of the species: whether it draws, and where it leaves the turtle per unit of its first scale.
uint surfaceDrawing(TurtleSpecies sp, uint sym) { return commandTable[sp.surfaces + kSurfaceWords * sym + 3u]; }
bool surfaceDrawn(TurtleSpecies sp, uint sym) { return surfaceDrawing(sp, sym) != kSurfaceNone; }
vec3 surfaceEnd(TurtleSpecies sp, uint sym) {
    uint at = sp.surfaces + kSurfaceWords * sym;
    return uintBitsToFloat(uvec3(commandTable[at], commandTable[at + 1u], commandTable[at + 2u]));
}

TurtleState initialState(TurtleSpecies sp) {
    TurtleState s;
    s.heading = vec4(0, 1, 0, sp.width);
    s.left = vec4(-1, 0, 0, sp.initialColor);
    s.up = vec4(0, 0, 1, sp.initialScale);
    s.position = vec4(0, 0, 0, sp.elasticity);
    return s;
}

// Whether a command needs the absolute state before it (and so cannot be a step).
bool isNonlinear(uint command, TurtleSpecies sp) {
    switch (command) {
    case kTurtleRollLevel: return sp.dollar == kDollarRolls;
    case kTurtleRollUpright:
    case kTurtleSetPosition:
    case kTurtleSetHeading:
    case kTurtleRotateWorldX:
    case kTurtleRotateWorldY:
    case kTurtleRotateWorldZ:
    case kTurtlePhototropism: return true;
    case kTurtleDraw: // tropism bends the heading before or after each segment, torque rolls before it
    case kTurtleDrawNoVertex: return sp.tropism.w != 0.0 || sp.torque.w != 0.0;
    case kTurtleMove:
    case kTurtleMoveNoVertex: return (sp.tropism.w != 0.0 && sp.tropismRule != kTropismTorque) || sp.torque.w != 0.0;
    default: return false;
    }
}

// The scale a sub-L-system call `?(label, s)` at i applies: s (1 without it, or where it could not be undone).
float callScale(uint i) {
    float s = paramAt(i, 1u, 1.0);
    return s != 0.0 && !isinf(s) && !isnan(s) ? s : 1.0;
}

// The scale of the call that the `$` at i returns from: the nearest call before it in the plant's string that no
// `$` between them closes (turtle_cpu.cpp keeps the calls on a stack); 1 where none, as cpfg ignores such a `$`.
float returnedScale(uint i) {
    uint plant = plantOf(i);
    uint begin = plantStarts[plant], end = plantStarts[plant + 1u];
    uint open = 1u;
    for (uint k = i; k > begin; --k) {
        uint command = commandAt(k - 1u, begin, end);
        if (command == kTurtleSubLsystemCall && hasParam(k - 1u)) {
            if (--open == 0u) return callScale(k - 1u);
        } else if (command == kTurtleRollLevel) {
            ++open;
        }
    }
    return 1.0;
}

// x -> x + delta, or x -> the module's first parameter when it has one.
vec2 addOrSet(uint i, float delta) { return hasParam(i) ? vec2(0.0, paramAt(i, 0u, 0.0)) : vec2(1.0, delta); }

// The step of a command that does not need the absolute state (identity for those that draw only).
TurtleStep commandStep(uint command, uint i, TurtleSpecies sp) {
    TurtleStep t = identityStep();
    float angle = paramAt(i, 0u, sp.angleDegrees) * kDegrees;
    switch (command) {
    case kTurtleDraw:
    case kTurtleDrawNoVertex:
    case kTurtleMove:
    case kTurtleMoveNoVertex: t.scaledTranslation.x = paramAt(i, 0u, sp.step); break;
    case kTurtleSurface:
        if (surfaceDrawn(sp, symbolAt(i))) t.scaledTranslation.xyz = paramAt(i, 0u, 1.0) * surfaceEnd(sp, symbolAt(i));
        break;
    case kTurtleTurnLeft: t = turnStep(0, 1, angle); break;
    case kTurtleTurnRight: t = turnStep(0, 1, -angle); break;
    case kTurtlePitchDown: t = turnStep(0, 2, -angle); break;
    case kTurtlePitchUp: t = turnStep(0, 2, angle); break;
    // cpfg's roll: its up is ours reversed (turtle_cpu.cpp).
    case kTurtleRollLeft: t = turnStep(2, 1, -angle); break;
    case kTurtleRollRight: t = turnStep(2, 1, angle); break;
    case kTurtleTurnAround:
        t.heading.x = -1.0;
        t.left.y = -1.0;
        break;
    case kTurtlePitchRadians: t = turnStep(0, 2, -paramAt(i, 0u, 0.0)); break;
    case kTurtleRollRadians: t = turnStep(2, 1, paramAt(i, 0u, 0.0)); break;
    case kTurtleTilt: {
        float roll = paramAt(i, 1u, 0.0);
        t = composeSteps(composeSteps(turnStep(2, 1, roll), turnStep(0, 2, -paramAt(i, 0u, 0.0))),
                         turnStep(2, 1, -roll));
        break;
    }
    // A width is set in the scale before the command: width -> a width + (translation.w) scale.
    case kTurtleWidthUp:
        t.widthColor.xy = vec2(hasParam(i) ? 0.0 : 1.0, 0.0);
        t.translation.w = hasParam(i) ? paramAt(i, 0u, 0.0) : sp.widthIncrement;
        break;
    case kTurtleWidthDown:
        t.widthColor.xy = vec2(hasParam(i) ? 0.0 : 1.0, 0.0);
        t.translation.w = hasParam(i) ? paramAt(i, 0u, 0.0) : -sp.widthIncrement;
        break;
    case kTurtleColorUp: t.widthColor.zw = addOrSet(i, sp.colorIncrement); break;
    case kTurtleColorDown: t.widthColor.zw = addOrSet(i, -sp.colorIncrement); break;
    case kTurtleScaleSet:
        if (hasParam(i)) t.scaleElasticity.xy = vec2(0.0, paramAt(i, 0u, 0.0));
        break;
    case kTurtleScaleUp:
    case kTurtleAlive: t.scaleElasticity.x = paramAt(i, 0u, 1.0); break;
    case kTurtleScaleDown: {
        float d = paramAt(i, 0u, 1.0);
        t.scaleElasticity.x = 1.0 / (d != 0.0 ? d : 1.0);
        break;
    }
    // A sub-L-system's lengths and widths are its call's scale times the caller's, until its `$`.
    case kTurtleSubLsystemCall:
        if (hasParam(i) && sp.dollar == kDollarReturns) {
            t.scaleElasticity.x = callScale(i);
            t.widthColor.x = callScale(i);
        }
        break;
    case kTurtleRollLevel: // `$` where it does not roll (isNonlinear): the return from a sub-L-system
        if (sp.dollar == kDollarReturns) {
            float back = 1.0 / returnedScale(i);
            t.scaleElasticity.x = back;
            t.widthColor.x = back;
        }
        break;
    case kTurtleElasticitySet:
        if (paramCountAt(i) > 1u) t.scaleElasticity.zw = vec2(0.0, paramAt(i, 1u, 0.0));
        break;
    case kTurtleElasticityUp: t.scaleElasticity.w = paramAt(i, 1u, sp.elasticityIncrement); break;
    case kTurtleElasticityDown: t.scaleElasticity.w = -paramAt(i, 1u, sp.elasticityIncrement); break;
    case kTurtleTropism:
        if (hasParam(i)) t.scaleElasticity.zw = vec2(0.0, paramAt(i, 0u, 0.0));
        break;
    case kTurtleElasticityStep:
        if (hasParam(i)) t.scaleElasticity.zw = vec2(0.0, paramAt(i, 0u, 0.0));
        else t.scaleElasticity.w = sp.elasticityIncrement;
        break;
    default: break;
    }
    return t;
}

// The state after a non-linear command, from the state before it.
TurtleState applyNonlinear(TurtleState s, uint command, uint i, TurtleSpecies sp) {
    Frame f = frameOf(s);
    switch (command) {
    case kTurtleDraw:
    case kTurtleDrawNoVertex:
    case kTurtleMove:
    case kTurtleMoveNoVertex:
        // cpfg's tropism lines bend before the move, and its torque rolls after them.
        if (sp.tropismRule == kTropismCpfgTropism) bendAsCpfgTropism(f, sp.tropism.xyz, s.position.w);
        rollByTorque(f, sp.torque.xyz);
        setFrame(s, f);
        s = applyStep(s, commandStep(command, i, sp));
        f = frameOf(s);
        if (sp.tropismRule == kTropismCpfgDirection) bendAsCpfgDirection(f, sp.tropism.xyz, s.position.w);
        else if (sp.tropismRule == kTropismTorque) bend(f, sp.tropism.xyz, s.position.w);
        break;
    case kTurtleRollLevel: rollLevel(f); break; // only where `$` rolls (isNonlinear)
    case kTurtleRollUpright: rollUpright(f); break;
    case kTurtlePhototropism: {
        vec3 d = vec3(paramAt(i, 1u, 0.0), paramAt(i, 2u, 0.0), paramAt(i, 3u, 0.0));
        if (length(d) > 0.0) bend(f, normalize(d), paramAt(i, 0u, 0.0));
        break;
    }
    case kTurtleRotateWorldX: rotateFrame(f, vec3(1, 0, 0), paramAt(i, 0u, 0.0)); break;
    case kTurtleRotateWorldY: rotateFrame(f, vec3(0, 1, 0), paramAt(i, 0u, 0.0)); break;
    case kTurtleRotateWorldZ: rotateFrame(f, vec3(0, 0, 1), paramAt(i, 0u, 0.0)); break;
    case kTurtleSetPosition:
        s.position.xyz = vec3(paramAt(i, 0u, s.position.x), paramAt(i, 1u, s.position.y), paramAt(i, 2u, s.position.z));
        break;
    case kTurtleSetHeading: {
        vec3 h = vec3(paramAt(i, 0u, 0.0), paramAt(i, 1u, 0.0), paramAt(i, 2u, 0.0));
        if (paramCountAt(i) >= 6u)
            setHeadingAndUp(f, h, vec3(paramAt(i, 3u, 0.0), paramAt(i, 4u, 0.0), paramAt(i, 5u, 0.0)));
        else if (paramCountAt(i) >= 3u)
            setHeading(f, h);
        break;
    }
    default: break;
    }
    setFrame(s, f);
    return s;
}
