// Overwritten assignments across includes, as OpenSCAD 2021.01 warns of
// them: in one file, an include overriding the main file; never for the
// same line of a file included twice, nor the main file overriding an
// include (issue 18)
main_a = 1;
include <lib/assigns.scad>
include <lib/assigns.scad>
include <lib/../lib/assigns.scad>
lib_b = 4;
z = 1;
z = 2;
z = 3;
echo(lib_a, lib_b, main_a, z);
