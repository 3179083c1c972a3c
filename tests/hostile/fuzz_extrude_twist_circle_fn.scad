// libFuzzer timeout pipeline-timeout-e86112bf (twisted extrusion of a circle at $fn = 1e9): fragments capped
linear_extrude(height = 1, twist = 90) circle(1, $fn = 1e9);
