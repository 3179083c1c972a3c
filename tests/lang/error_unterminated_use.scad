// A use never closed
use <lib/library.scad
echo(2);
