include <does_not_exist.scad>
use <neither_does_this.scad>
include <>
use <>
cube();
