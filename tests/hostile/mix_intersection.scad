intersection() { circle(3); sphere(2); }
