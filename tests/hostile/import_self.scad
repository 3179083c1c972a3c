import("import_self.scad");
surface("import_self.scad");
import(file = 42);
surface(file = [1, 2]);
