import("nope.stl");
import("nope.off");
import("");
import();
surface("nope.dat");
surface("nope.png");
surface();
