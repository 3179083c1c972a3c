// A 24-gon frustum: plane facets 15° apart whose edges, at 45° to the axes,
// pass through grid edges every other layer of a grid centred on the model
// (a contour vertex held beside such an edge, off both facets, once left it
// 872 triangles).  OpenSCAD writes it as 92.
linear_extrude(10, scale = 0.5) polygon([for (i = [0:23]) 10 * [cos(15 * i), sin(15 * i)]]);
