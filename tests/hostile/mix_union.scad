union() { cube(); square(); }
