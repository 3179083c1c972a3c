module c(n) { if (n > 0) c(n - 1) children(); else children(); }
c(20000) cube();
