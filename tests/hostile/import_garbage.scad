import("data/garbage.stl");
import("data/garbage.off");
import("data/huge_counts.off");
import("data/empty.obj");
surface("data/garbage.dat");
surface("data/ragged.dat");
surface("data/garbage.png");
