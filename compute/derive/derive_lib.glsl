// Functions every generated derivation kernel shares: reading the module stream, branch-aware context walks
// (brackets matched by derive/depth_tree.glsl, which comes before this file), error reports, and
// double-precision elementary functions.
//
// Expects before it: the inputs symIn, parIn and bracketPartners with their accessors symInAt(i) ...
// (codegen::Bindings::addInput), the buffers depthTree, levelInfo and errors, the push constants
// `pc` (DerivePush), shared/random.h, shared/derive_layout.h, derive/depth_tree.glsl and contextSkipWord(word),
// the species' context filter (codegen::contextSkipBits, as constants or from the contextSkip buffer).

uint symOf(uint i) { return symInAt(i) & kSymbolMask; }
uint countOf(uint i) { return symInAt(i) >> kSymbolBits; }
double paramOf(uint i, uint k) { return double(parInAt(i * pc.stride + k)); }
// The context filter holds one row of bits per species; `row` is the first word of the species' row.
bool skipped(uint sym, uint row) { return ((contextSkipWord(row + (sym >> 5u)) >> (sym & 31u)) & 1u) != 0u; }

// matchOpen and matchClose by the partners found once per string (derive/bracket_partners.comp).
uint closingBracket(uint s, uint pEnd) {
    uint j = bracketPartnersAt(s);
    return j < pEnd ? j : kNoModule;
}
uint openingBracket(uint j, uint pBegin) {
    uint open = bracketPartnersAt(j); // a `[` or kNoModule (bracket_partners.comp, or carried by a write pass)
    return (open == kNoModule || open < pBegin || open >= j) ? kNoModule : open;
}

// The `]` that closes the branch containing position s (or pEnd at the top level or when unmatched).
uint endOfBranch(uint s, uint pBegin, uint pEnd) {
    if (s >= pEnd) return pEnd;
    uint sym = symOf(s);
    int before = depthAt(0u, s) - (sym == kOpen ? 1 : sym == kClose ? -1 : 0);
    int k = lastBelow(int(s) - 1, before);
    if (k == kNoneBelow) return pEnd;
    uint open = uint(k + 1);
    if (open < pBegin || open >= s || symOf(open) != kOpen) return pEnd;
    uint close = closingBracket(open, pEnd);
    return close == kNoModule ? pEnd : close;
}

// The word (symbol and parameter count) of the module where the last walk stopped, so that a caller comparing it
// with a pattern module does not fetch it again.
uint walkWord = 0u;

// Right context: moves s to the module the next pattern symbol is compared with. Skipped symbols pass, closed
// branches pass unless the pattern `enters` one with `[`; false at the end of the plant, except that a `ring`
// L-system's walk goes on from the plant's start once per pattern (`wrapped`), as the CPU reference's.
bool rightWalk(inout uint s, bool enters, uint pBegin, uint pEnd, uint skipRow, bool ring, inout bool wrapped) {
    for (;;) {
        if (s >= pEnd) {
            if (!ring || wrapped) return false;
            wrapped = true;
            s = pBegin;
            continue;
        }
        uint word = symInAt(s), sym = word & kSymbolMask;
        if (skipped(sym, skipRow)) {
            ++s;
        } else if (!enters && sym == kOpen) {
            uint close = closingBracket(s, pEnd);
            if (close == kNoModule) return false;
            s = close + 1u;
        } else {
            walkWord = word;
            return true;
        }
    }
    return false;
}

// Left context: moves s to the next module to compare, skipping branches to the left and passing `[`; a ring
// L-system's walk goes on from the plant's end once per pattern.
bool leftWalk(inout int s, uint pBegin, uint pEnd, uint skipRow, bool ring, inout bool wrapped) {
    for (;;) {
        if (s < int(pBegin)) {
            if (!ring || wrapped) return false;
            wrapped = true;
            s = int(pEnd) - 1;
            continue;
        }
        uint word = symInAt(uint(s)), sym = word & kSymbolMask;
        if (sym == kClose) {
            uint open = openingBracket(uint(s), pBegin);
            if (open == kNoModule) return false;
            s = int(open) - 1;
        } else if (sym == kOpen || skipped(sym, skipRow)) {
            --s;
        } else {
            walkWord = word;
            return true;
        }
    }
    return false;
}

// The walks of L-systems that are not rings.
bool walkRight(inout uint s, bool enters, uint pEnd, uint skipRow) {
    bool wrapped = false;
    return rightWalk(s, enters, 0u, pEnd, skipRow, false, wrapped);
}
bool walkLeft(inout int s, uint pBegin, uint skipRow) {
    bool wrapped = false;
    return leftWalk(s, pBegin, 0u, skipRow, false, wrapped);
}

// A module's productions mostly start their context walks at the same place, so each invocation remembers its
// last walk in each direction and repeats none. Within one invocation pBegin, pEnd and skipRow stay the same
// for a given start (one plant at a time), so the start and whether the pattern enters branches are the key.
// (Ring L-systems walk without these: whether a walk may wrap depends on the pattern's earlier walks.)
uint rightMemoStart = kNoModule, rightMemoEnd = 0u;
bool rightMemoEnters = false, rightMemoFound = false;
bool rightAdvance(inout uint s, uint want, uint pEnd, uint skipRow) {
    bool enters = want == kOpen;
    if (s != rightMemoStart || enters != rightMemoEnters) {
        rightMemoStart = s;
        rightMemoEnters = enters;
        rightMemoEnd = s;
        rightMemoFound = walkRight(rightMemoEnd, enters, pEnd, skipRow);
    }
    s = rightMemoEnd;
    return rightMemoFound;
}

int leftMemoStart = -2, leftMemoEnd = 0;
bool leftMemoFound = false;
bool leftAdvance(inout int s, uint pBegin, uint skipRow) {
    if (s != leftMemoStart) {
        leftMemoStart = s;
        leftMemoEnd = s;
        leftMemoFound = walkLeft(leftMemoEnd, pBegin, skipRow);
    }
    s = leftMemoEnd;
    return leftMemoFound;
}

// Where the first module of the context patterns lies, walked once per module by the generated
// prefetchContexts() before the productions try their patterns: lavapipe runs every branch of a kernel for all
// invocations of a subgroup, so a walk written into each production cost a loop per production.
// The modules' words (symbol and parameter count) come along, so a pattern module is one comparison.
uint firstRight = 0u, firstRightBranch = 0u;
int firstLeft = 0;
bool firstRightFound = false, firstRightBranchFound = false, firstLeftFound = false;
uint firstRightWord = 0u, firstRightBranchWord = 0u, firstLeftWord = 0u;

// The alternative of a production with several (prob) that a parallel pass applied, which a match pass records
// with its choice, and the one a writing pass is given to apply in mode 3 (production_codegen.h) instead of
// drawing it again.
uint chosenAlternative = 0u;
uint givenAlternative = 0u;

// The first evaluation error of the pass wins; the host turns the code into a located message.
void reportError(uint code) { atomicCompSwap(errors[0], 0u, code + 1u); }

// A zero the compiler cannot see, for the literal zeros of products and quotients: Mesa 22.3 folds a double x * 0.0
// to 0 even where the kernel asks to keep infinities and NaN, while inf * 0 is NaN on the CPU (and in cpfg).
double opaqueZero() { return double(pc.zero); }

// Modules of the stream the kernel walks, set first thing in main(): pc.count, or, for a count only the device
// knows (kCountOnDevice: steps recorded one after the other), the last entry of the input's plant table.
uint moduleCount;
uint streamCount() { return pc.count != kCountOnDevice ? pc.count : plantStartAt(pc.plants); }

// lavapipe ends every loop of an invocation once the invocation has run 65535 loop iterations in all, and the code
// after a loop then runs as if the loop had ended by itself. A check after a loop cannot see that: the compiler
// knows only the loop's own exits and folds the check away. So every generated main() whose loops may run long
// (codegen::mayLoopLong) ends with this loop of pc.loopProbeTrips iterations (a number the compiler cannot know),
// which stops after one exactly when the iterations are spent, and raises kFlagLoopCut.
// - The driver counts iterations per subgroup (one SIMD program), so the loop runs once for all its invocations.
// - The count steps by reading its next value from the push constants, so LLVM finds no induction variable to
//   analyse: asked about a counted loop at the end of a large kernel, its analysis walks every condition before it
//   and can take minutes. A float count does not survive its optimisations, and counting by atomics in shared
//   memory costs lavapipe a loop over the invocations for every access.
void reportLoopsCut() {
    uint trips = 0u;
    do {
        trips = pc.loopProbeCounts[trips];
    } while (trips < pc.loopProbeTrips);
    if (trips != pc.loopProbeTrips) atomicOr(errors[1], kFlagLoopCut);
}

// ---- double precision elementary functions (GLSL provides sqrt, floor, ... for doubles, not these) ----

const double kPi = 3.14159265358979311600LF;
const double kHalfPiHi = 1.57079632679489655800LF;
const double kHalfPiLo = 6.12323399573676603587e-17LF;
const double kLn2Hi = 6.93147180369123816490e-01LF;
const double kLn2Lo = 1.90821492927058770002e-10LF;

double sinPoly(double r) {
    double r2 = r * r;
    return r * (1.0LF + r2 * (-1.0LF / 6.0LF + r2 * (1.0LF / 120.0LF + r2 * (-1.0LF / 5040.0LF + r2 * (1.0LF / 362880.0LF
           + r2 * (-1.0LF / 39916800.0LF + r2 * (1.0LF / 6227020800.0LF + r2 * (-1.0LF / 1307674368000.0LF
           + r2 * (1.0LF / 355687428096000.0LF)))))))));
}
double cosPoly(double r) {
    double r2 = r * r;
    return 1.0LF + r2 * (-0.5LF + r2 * (1.0LF / 24.0LF + r2 * (-1.0LF / 720.0LF + r2 * (1.0LF / 40320.0LF
           + r2 * (-1.0LF / 3628800.0LF + r2 * (1.0LF / 479001600.0LF + r2 * (-1.0LF / 87178291200.0LF
           + r2 * (1.0LF / 20922789888000.0LF))))))));
}
// sin or cos (cosine when `cosine`) of x radians, by reduction to [-pi/4, pi/4].
double sinCosD(double x, bool cosine) {
    double k = floor(x / kHalfPiHi + 0.5LF);
    double r = (x - k * kHalfPiHi) - k * kHalfPiLo;
    int quadrant = int(k - 4.0LF * floor(k / 4.0LF)) + (cosine ? 1 : 0);
    quadrant &= 3;
    double s = sinPoly(r), c = cosPoly(r);
    if (quadrant == 0) return s;
    if (quadrant == 1) return c;
    if (quadrant == 2) return -s;
    return -c;
}
double sinD(double x) { return sinCosD(x, false); }
double cosD(double x) { return sinCosD(x, true); }

double expD(double x) {
    if (x > 709.0LF) return 1.0LF / 0.0LF;
    if (x < -745.0LF) return 0.0LF;
    double k = floor(x / (kLn2Hi + kLn2Lo) + 0.5LF);
    double r = (x - k * kLn2Hi) - k * kLn2Lo;
    double term = 1.0LF, sum = 1.0LF;
    for (int n = 1; n <= 16; ++n) {
        term *= r / double(n);
        sum += term;
    }
    return ldexp(sum, int(k));
}

double logD(double x) {
    if (x < 0.0LF) return 0.0LF / 0.0LF;
    if (x == 0.0LF) return -1.0LF / 0.0LF;
    int e;
    double m = frexp(x, e); // x = m * 2^e, m in [0.5, 1)
    if (m < 0.70710678118654752440LF) {
        m *= 2.0LF;
        --e;
    }
    double s = (m - 1.0LF) / (m + 1.0LF), s2 = s * s;
    double sum = 0.0LF, power = s;
    for (int n = 1; n <= 27; n += 2) {
        sum += power / double(n);
        power *= s2;
    }
    return 2.0LF * sum + double(e) * kLn2Hi + double(e) * kLn2Lo;
}

double powD(double a, double b) {
    if (b == 0.0LF) return 1.0LF;
    if (a == 0.0LF) return b > 0.0LF ? 0.0LF : 1.0LF / 0.0LF;
    if (b == floor(b) && abs(b) <= 64.0LF) {
        // Whole exponents by repeated squaring (as exact as the C library for these). Seven squarings cover
        // |b| <= 64; a fixed count unrolls, where a loop on the bits of b made lavapipe's compile of a kernel with
        // a few powers take seconds.
        double result = 1.0LF, base = a;
        int n = int(abs(b));
        for (int bit = 0; bit < 7; ++bit) {
            if ((n & (1 << bit)) != 0) result *= base;
            base *= base;
        }
        return b < 0.0LF ? 1.0LF / result : result;
    }
    if (a < 0.0LF) return 0.0LF / 0.0LF;
    return expD(b * logD(a));
}

// atan for |x| <= 1 by two argument halvings and a Taylor series.
double atanSmall(double x) {
    double y = x / (1.0LF + sqrt(1.0LF + x * x));
    y = y / (1.0LF + sqrt(1.0LF + y * y));
    double y2 = y * y, term = y, sum = 0.0LF;
    for (int n = 1; n <= 39; n += 2) {
        sum += term / double(n);
        term *= -y2;
    }
    return 4.0LF * sum;
}
double atanD(double x) {
    if (abs(x) <= 1.0LF) return atanSmall(x);
    double r = 2.0LF * kHalfPiHi - atanSmall(1.0LF / abs(x));
    return x < 0.0LF ? -r : r;
}
double atan2D(double y, double x) {
    if (x > 0.0LF) return atanD(y / x);
    if (x < 0.0LF) return y >= 0.0LF ? atanD(y / x) + kPi : atanD(y / x) - kPi;
    if (y > 0.0LF) return kHalfPiHi;
    if (y < 0.0LF) return -kHalfPiHi;
    return 0.0LF;
}
double asinD(double x) {
    if (abs(x) > 1.0LF) return 0.0LF / 0.0LF;
    if (abs(x) == 1.0LF) return x * kHalfPiHi;
    return atanD(x / sqrt(1.0LF - x * x));
}
double acosD(double x) { return kHalfPiHi - asinD(x) + kHalfPiLo; }

const double kDegrees = 57.29577951308232286465LF;
