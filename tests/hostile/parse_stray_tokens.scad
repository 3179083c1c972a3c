cube() sphere() ;;;; [1, 2, 3];
1 + 2;
"string";
module m() = 3;
function f() { cube(); }
