module m(n) { if (n > 0) m(n - 1) { children(); children(); } else children(); }
m(30) cube();
