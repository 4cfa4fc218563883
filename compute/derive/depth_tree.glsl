// Bracket matching on the depth min-tree, shared by the derivation kernels and the turtle kernels.
//
// Brackets are matched in parallel from the bracket depth D (an inclusive prefix sum of +1 for `[` and -1 for
// `]`): the `]` matching a `[` at i is the first j > i with D[j] < D[i], and the `[` matching a `]` at j follows
// the last k < j with D[k] <= D[j]. Both are found in O(log n) on a binary tree of minima of D (levelInfo holds
// each level's offset in depthTree and its size), so arbitrarily long branches cost nothing extra.
//
// Expects before it: the buffers depthTree (int) and levelInfo (uint) and shared/derive_layout.h; the includer
// defines symOf(i), the symbol of module i.

const uint kOpen = 0u;
const uint kClose = 1u;
const int kNoneBelow = -2; // lastBelow: nothing found; -1 means the virtual depth 0 before the string

uint symOf(uint i);

int depthAt(uint level, uint index) { return depthTree[levelInfo[level] + index]; }
uint levelSize(uint level) { return levelInfo[kMaxDepthLevels + level]; }

// The first index j >= from with D[j] < v, or kNoModule.
uint firstBelow(uint from, int v) {
    uint index = from;
    uint level = 0u;
    for (;;) {
        if (index >= levelSize(level)) return kNoModule;
        if (depthAt(level, index) < v) break;
        while ((index & 1u) == 1u) {
            index >>= 1u;
            ++level;
        }
        ++index;
    }
    while (level > 0u) {
        --level;
        index <<= 1u;
        if (depthAt(level, index) >= v) ++index;
    }
    return index;
}

// The last index k <= to with D[k] < v; -1 when only the virtual depth 0 before the string is below v;
// kNoneBelow when nothing is.
int lastBelow(int to, int v) {
    int index = to;
    uint level = 0u;
    for (;;) {
        if (index < 0) return v > 0 ? -1 : kNoneBelow;
        if (depthAt(level, uint(index)) < v) break;
        while ((index & 1) == 0) {
            if (index == 0) return v > 0 ? -1 : kNoneBelow;
            index >>= 1;
            ++level;
        }
        --index;
    }
    while (level > 0u) {
        --level;
        index = index * 2 + 1;
        if (uint(index) >= levelSize(level) || depthAt(level, uint(index)) >= v) --index;
    }
    return index;
}

// The `]` closing the `[` at s within the plant ending at pEnd, or kNoModule.
uint matchOpen(uint s, uint pEnd) {
    uint j = firstBelow(s + 1u, depthAt(0u, s));
    return (j == kNoModule || j >= pEnd) ? kNoModule : j;
}

// The `[` opened by the `]` at j within the plant starting at pBegin, or kNoModule.
uint matchClose(uint j, uint pBegin) {
    int k = lastBelow(int(j) - 1, depthAt(0u, j) + 1);
    if (k == kNoneBelow) return kNoModule;
    uint open = uint(k + 1);
    return (open < pBegin || open >= j || symOf(open) != kOpen) ? kNoModule : open;
}
