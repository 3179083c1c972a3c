// import() of an .svg prints center and dpi in .csg, as openscad 2021.01;
// its dpi warning; id is no parameter of 2021.01's (issue 18)
import("a.svg", dpi=96, center=true);
import("a.SVG", dpi=0);
import("a.svg", dpi="x", center=1);
import("b.dxf", dpi=96, center=true);
import("c.svg", id="q");
