// linear_extrude of a concave polygon: a five-pointed star prism.  The tips
// are 69° wide: cut off by the grid, they are put back where their plane
// faces meet (src/mesh/crease.c).
linear_extrude(height = 4)
    polygon([for (i = [0:9]) let(r = i % 2 == 0 ? 10 : 6, a = 90 + 36 * i) [r * cos(a), r * sin(a)]]);
