// A 30-gon prism: 30 plane facets meeting at 12°, under any feature angle
// that tells a curved surface's normals from a sharp edge.  OpenSCAD writes
// it as 116 triangles; a mesh that follows its facets needs no more.
linear_extrude(8) polygon([for (i = [0:29]) 5 * [cos(12 * i), sin(12 * i)]]);
