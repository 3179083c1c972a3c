// SVG files that are not well-formed XML, or well-formed with numbers out
// of range, degenerate shapes, deep nesting and entity expansion: each is
// a note (or nothing) and never a crash.
import("data/malformed.svg");
import("data/garbage.svg");
import("data/numbers.svg");
import("data/deep.svg");
import("data/entities.svg");
import("data/missing.svg", center = true);
cube(1);
