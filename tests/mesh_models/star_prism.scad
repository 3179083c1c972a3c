// linear_extrude of a concave polygon: a five-pointed star prism.  The tips
// are 69° wide: a tip sharper than the grid can resolve loses up to about
// h / sin(half its angle) of its length (see README, Meshes).
linear_extrude(height = 4)
    polygon([for (i = [0:9]) let(r = i % 2 == 0 ? 10 : 6, a = 90 + 36 * i) [r * cos(a), r * sin(a)]]);
