import("/dev/null");
import("/dev/zero");
import("/dev/zero.stl");
surface("/dev/zero");
surface("/dev/null");
import(".");
surface("/");
