// Grows a plant's box (in plant-local coordinates) by an organ's: the includer declares `plantBounds`, each
// plant's minima at 4p and maxima at 4 (plants + p), and includes turtle_math.glsl and organ_bounds.glsl first.
void growPlantBounds(uint plant, OrganInstance o) {
    Box b = organBox(o);
    for (uint axis = 0u; axis < 3u; ++axis) {
        atomicMin(plantBounds[plant * 4u + axis], boundsKey(b.lo[axis]));
        atomicMax(plantBounds[(pc.plants + plant) * 4u + axis], boundsKey(b.hi[axis]));
    }
}
