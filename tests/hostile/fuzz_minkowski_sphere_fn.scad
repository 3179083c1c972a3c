// libFuzzer timeout eval-timeout-46193eef (minkowski of two spheres at $fn = 1e9): a smooth leaf sums at 64 fragments, 4·10^6 points
minkowski() { sphere(1, $fn = 1e9); sphere(1, $fn = 1e9); }
