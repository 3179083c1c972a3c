// An include never closed: reported on its own line
echo(1);
include <lib/helpers.scad

echo(2);
