// Plane facets meeting at slight angles: a 30-gon prism (12°), a 24-gon
// frustum (15°) and a faceted ring.
linear_extrude(8) polygon([for (i = [0:29]) 5 * [cos(12 * i), sin(12 * i)]]);
translate([14, 0, 0]) linear_extrude(8, scale = 0.4) polygon([for (i = [0:23]) 5 * [cos(15 * i), sin(15 * i)]]);
translate([7, 14, 0]) rotate_extrude($fn = 16) polygon([[2, 0], [5, 0], [4, 4], [2, 4]]);
