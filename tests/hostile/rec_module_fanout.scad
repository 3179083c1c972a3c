module m(n) { if (n > 0) { m(n - 1); m(n - 1); m(n - 1); } }
m(40);
