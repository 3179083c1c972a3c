// include <...> across lines, as openscad 2021.01 lexes it: line breaks
// split the name into pieces of which the last folder and last name count,
// and they are not counted as lines (the warning below is numbered lower)
include
<lib/
helpers.scad>
use <nowhere/
  lib/library.scad>
cube("a string");
echo(helper_value);
