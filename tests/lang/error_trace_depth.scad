// An error 21 modules deep: OpenSCAD prints at most 12 TRACE lines.
module m0() { assert(false); }
module m1() { m0(); }
module m2() { m1(); }
module m3() { m2(); }
module m4() { m3(); }
module m5() { m4(); }
module m6() { m5(); }
module m7() { m6(); }
module m8() { m7(); }
module m9() { m8(); }
module m10() { m9(); }
module m11() { m10(); }
module m12() { m11(); }
module m13() { m12(); }
module m14() { m13(); }
module m15() { m14(); }
module m16() { m15(); }
module m17() { m16(); }
module m18() { m17(); }
module m19() { m18(); }
module m20() { m19(); }
m20();
