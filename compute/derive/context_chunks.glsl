// A step's match pass by chunks, for devices that run a subgroup as one SIMD program on a CPU core (lavapipe):
// each invocation matches kContextChunk consecutive modules in order, where a context walk per module would run
// its loop, and gather its modules, for the whole subgroup.
//
// Where a module's first context module lies follows from its neighbour's, as the walks of derive_lib.glsl find
// it, where R(p) is walkRight from p + 1 and L(p) walkLeft from p - 1:
// - R(p - 1) is p when module p is compared (not skipped, not `[`), R(q) when p is a `[` closed at q (the walk
//   passes the branch), R(p) when p is skipped, and none at the plant's end or an unclosed `[`;
// - a pattern entering branches (`[` first) stops at the next module not skipped, `[` included;
// - L(p + 1) is p when module p is compared, L(o) when p is a `]` opened at o, L(p) when p is a `[` or skipped,
//   and none at the plant's start or an unopened `]`.
// So one pass from the chunk's end finds every R, one from its start every L, each in a step per module; only a
// partner outside the chunk, and the chunk's two ends, take a walk. The chunk is the fused scan's tile: the
// invocation sums its modules' successor counts as it goes.
//
// Expects before it: derive_lib.glsl and the generated matchChunkModule(i, word, plant, pBegin, pEnd), which
// matches module i (its word given) with the first context modules left in firstRight... and returns its
// successor count, leaving its choice in matchedChoice; kChunkRight, kChunkRightBranch and kChunkLeft, which of
// the first context modules the productions read; kSkipWords, the words of a species' context filter row;
// kSinglePlant, plantOf() and the buffers matchWords and tileSums.

// The chunk's modules, their bracket partners and their first context modules (kNoModule, or -1 on the left,
// where there is none).
uint chunkWords[kContextChunk];
uint chunkPartners[kContextChunk];
uint chunkRight[kContextChunk];
uint chunkRightWords[kContextChunk];
uint chunkRightBranch[kContextChunk];
uint chunkRightBranchWords[kContextChunk];
int chunkLeft[kContextChunk];
uint chunkLeftWords[kContextChunk];

// Module i's plant and the bounds of its string.
void chunkPlant(uint i, out uint plant, out uint pBegin, out uint pEnd) {
    plant = kSinglePlant ? 0u : plantOf(i);
    pBegin = kSinglePlant ? 0u : plantStartAt(plant);
    pEnd = kSinglePlant ? moduleCount : plantStartAt(plant + 1u);
}

uint skipRowOf(uint plant) { return speciesOf(plant) * kSkipWords; }

// Fills chunkRight and chunkRightBranch (and chunkWords, chunkPartners) from the chunk's end.
void chunkRightContexts(uint first, uint last) {
    uint plant, pBegin, pEnd;
    chunkPlant(last - 1u, plant, pBegin, pEnd);
    uint skipRow = skipRowOf(plant);
    uint right = last, rightWord = 0u;
    bool rightFound = false;
    if (kChunkRight) {
        rightFound = walkRight(right, false, pEnd, skipRow);
        rightWord = walkWord;
    }
    uint branch = last, branchWord = 0u;
    bool branchFound = false;
    if (kChunkRightBranch) {
        branchFound = walkRight(branch, true, pEnd, skipRow);
        branchWord = walkWord;
    }
    for (uint k = kContextChunk; k-- > 0u;) {
        uint p = first + k;
        if (p >= last) continue;
        if (p < pBegin) { // the end of an earlier plant (plants may be empty)
            while (p < pBegin) {
                --plant;
                pEnd = pBegin;
                pBegin = plantStartAt(plant);
            }
            skipRow = skipRowOf(plant);
            rightFound = false;
            branchFound = false;
        }
        chunkRight[k] = rightFound ? right : kNoModule;
        chunkRightWords[k] = rightWord;
        chunkRightBranch[k] = branchFound ? branch : kNoModule;
        chunkRightBranchWords[k] = branchWord;
        uint word = symInAt(p), sym = word & kSymbolMask;
        uint partner = bracketPartnersAt(p);
        chunkWords[k] = word;
        chunkPartners[k] = partner;
        if (skipped(sym, skipRow)) continue;
        if (kChunkRight) {
            if (sym != kOpen) {
                right = p;
                rightFound = true;
                rightWord = word;
            } else if (partner >= pEnd) {
                rightFound = false;
            } else if (partner < last) {
                right = chunkRight[partner - first];
                rightWord = chunkRightWords[partner - first];
                rightFound = right != kNoModule;
            } else {
                right = partner + 1u;
                rightFound = walkRight(right, false, pEnd, skipRow);
                rightWord = walkWord;
            }
        }
        branch = p;
        branchFound = true;
        branchWord = word;
    }
}

// Matches the chunk's modules from its start, finding each one's left context on the way, and stores their match
// words and the chunk's sum.
void matchChunk(uint chunk) {
    uint first = chunk * kContextChunk;
    if (first >= moduleCount) return;
    uint last = min(first + kContextChunk, moduleCount);
    chunkRightContexts(first, last);
    uint plant, pBegin, pEnd;
    chunkPlant(first, plant, pBegin, pEnd);
    uint skipRow = skipRowOf(plant);
    int left = int(first) - 1;
    uint leftWord = 0u;
    bool leftFound = false;
    if (kChunkLeft) {
        leftFound = walkLeft(left, pBegin, skipRow);
        leftWord = walkWord;
    }
    uint before = 0u;
    for (uint k = 0u; k < kContextChunk; ++k) {
        uint p = first + k;
        if (p >= last) break;
        if (p >= pEnd) { // the start of a later plant
            while (p >= pEnd) {
                ++plant;
                pBegin = pEnd;
                pEnd = plantStartAt(plant + 1u);
            }
            skipRow = skipRowOf(plant);
            leftFound = false;
        }
        chunkLeft[k] = leftFound ? left : -1;
        chunkLeftWords[k] = leftWord;
        firstLeft = left;
        firstLeftFound = leftFound;
        firstLeftWord = leftWord;
        firstRight = chunkRight[k];
        firstRightFound = firstRight != kNoModule;
        firstRightWord = chunkRightWords[k];
        firstRightBranch = chunkRightBranch[k];
        firstRightBranchFound = firstRightBranch != kNoModule;
        firstRightBranchWord = chunkRightBranchWords[k];
        // The productions' further walks remember theirs per module.
        rightMemoStart = kNoModule;
        leftMemoStart = -2;
        uint word = chunkWords[k];
        uint produced = matchChunkModule(p, word, plant, pBegin, pEnd);
        matchWords[p] = (before << kChoiceBits) | matchedChoice;
        before += produced;
        if (!kChunkLeft) continue;
        uint sym = word & kSymbolMask;
        if (sym == kClose) {
            uint open = chunkPartners[k];
            if (open == kNoModule || open < pBegin || open >= p) {
                leftFound = false;
            } else if (open >= first) {
                left = chunkLeft[open - first];
                leftWord = chunkLeftWords[open - first];
                leftFound = left >= 0;
            } else {
                left = int(open) - 1;
                leftFound = walkLeft(left, pBegin, skipRow);
                leftWord = walkWord;
            }
        } else if (sym != kOpen && !skipped(sym, skipRow)) {
            left = int(p);
            leftFound = true;
            leftWord = word;
        }
    }
    tileSums[chunk] = before;
}
