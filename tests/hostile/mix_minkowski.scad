minkowski() { cube(); circle(); }
minkowski() { square(); sphere(); }
