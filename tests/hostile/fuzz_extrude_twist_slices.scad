// libFuzzer timeout eval-timeout-e0c6bd51 (twisted linear_extrude, slices = 1e9 and -5): slices capped
linear_extrude(height = 1, twist = 10, slices = 1e9) square();
linear_extrude(height = 1, twist = 10, slices = -5) square();
