// Trigonometry in degrees bit for bit as openscad computes it: each result
// printed exactly (53-bit mantissa in three exact parts) (issue 18)
function ex(a, e=0) = a >= 1 ? ex(a/2, e+1) : a < 0.5 ? ex(a*2, e-1) : e;
function bits(v) = v == 0 ? (1/v < 0 ? "-0" : "0") : v != v ? "nan" : abs(v) == 1/0 ? str(v) :
  let(a = abs(v), e = ex(a), m = a * pow(2, 53 - e))
  str(v < 0 ? "-" : "", floor(m / 1e12), ":", floor(m / 1e6) % 1e6, ":", m % 1e6, "e", e);
xs = [for (i = [-720:7.5:720]) i];
us = [for (i = [-1:0.0625:1]) i];
for (x = xs) echo(x, bits(sin(x)), bits(cos(x)), bits(tan(x)));
for (x = [1e10, 123456.789, -1e15, 0.1, 1/3, 89.999999, 90.000001]) echo(x, bits(sin(x)), bits(cos(x)), bits(tan(x)));
for (u = concat(us, [0.5, sqrt(3)/2, sqrt(2)/2, 1/sqrt(3), sqrt(3), 2, -0.3])) echo(u, bits(asin(u)), bits(acos(u)), bits(atan(u)));
for (y = [-2:0.5:2], x = [-2:0.5:2]) echo(y, x, bits(atan2(y, x)));
