// args: --imgsize=400,300
// text() of any size, as 2021.01 draws it: FreeType refuses more than 65535
// pixels per em (size 3000 here) and we drew nothing past it.
text("Big", size = 5000);
translate([0, -4000]) text("ok", size = 2500);
