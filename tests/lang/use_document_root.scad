// A used file's module: its parameter warning names the file relative to
// its own folder; a file it reads that is only in the main file's folder is
// found there, with openscad 2021.01's DEPRECATED line (issue 18)
use <lib/doc_root_module.scad>
doc_root_module();
