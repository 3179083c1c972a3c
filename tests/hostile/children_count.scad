module m() echo($children);
m() { for (i = [0:1e5]) cube(); }
$children = 1e9;
children();
