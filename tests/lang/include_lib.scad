// include <…> brings in everything, as if pasted here
include <lib/helpers.scad>
echo(helper_value, twice(4));
show_helper();
include <lib/sub/nested.scad>
echo(nested_value);
