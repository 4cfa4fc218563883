// The light grid's voxels and what an organ puts in them (src/grow/light_grid.cpp does the same on the CPU).
// Needs shared/organ_layout.h, shared/light_layout.h and a push block `pc` of LightGridPush.

// The grid coordinates of the voxel holding point p, whole numbers, outside the grid or not.
vec3 cellAt(vec3 p) {
    precise vec3 inGrid = (p - pc.origin.xyz) * pc.inverseSide;
    return floor(inGrid);
}

// The voxel of a cell, or -1 outside the grid.
int voxelOfCell(vec3 cell) {
    if (any(lessThan(cell, vec3(0.0))) || cell.x >= float(pc.sizeX) || cell.y >= float(pc.sizeY) ||
        cell.z >= float(pc.sizeZ))
        return -1;
    return int((uint(cell.z) * pc.sizeY + uint(cell.y)) * pc.sizeX + uint(cell.x));
}

// The voxel holding point p, or -1 outside the grid.
int voxelAt(vec3 p) { return voxelOfCell(cellAt(p)); }

// Where an organ stands for the light: the middle of its segment or blade, its centre, its triangle's centroid.
vec3 organCentre(OrganInstance o) {
    precise vec3 centre = o.position.xyz;
    if (o.kind == kOrganStem || o.kind == kOrganLeaf) centre = o.position.xyz + 0.5 * o.position.w * o.heading.xyz;
    if (o.kind == kOrganTriangle) centre = (o.position.xyz + o.heading.xyz + o.up.xyz) * kOneThird;
    return centre;
}

// Where an organ reaches to: the end of its segment or blade; a triangle's centroid, a sphere's or disc's centre.
vec3 organTip(OrganInstance o) {
    precise vec3 tip = o.position.xyz + o.position.w * o.heading.xyz;
    return o.kind == kOrganStem || o.kind == kOrganLeaf ? tip : organCentre(o);
}

// The area an organ shades with: a blade's (its shape's area at its length and width, `shapeArea`), a segment's
// side seen across it (length times diameter), a disc's or sphere's cross-section, a triangle's.
float organShadingArea(OrganInstance o, float shapeArea) {
    precise float area = 3.14159265 * o.heading.w * o.heading.w;
    if (o.kind == kOrganLeaf) area = o.position.w * o.heading.w * shapeArea;
    if (o.kind == kOrganStem) area = o.position.w * (o.heading.w + o.up.w);
    if (o.kind == kOrganTriangle) area = 0.5 * length(cross(o.heading.xyz - o.position.xyz, o.up.xyz - o.position.xyz));
    return area;
}
