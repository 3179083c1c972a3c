offset(r = 1, $fn = 1e9) square();
offset(r = 1e300) square();
offset(delta = 0 / 0) square();
offset(r = -1e300) circle(5);
