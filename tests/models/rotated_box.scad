// A box turned obliquely to every axis: its edges and corners run through
// the sampling grid at no angle it favours.  OpenSCAD writes it as 12
// triangles; the contour cuts its edges and corners off where a cell sees
// only one of their faces, and src/mesh/crease.c puts them back.
rotate([20, 30, 40]) cube([14, 9, 6], center = true);
