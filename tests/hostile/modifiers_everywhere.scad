#difference() { #cube(); %sphere(); !cylinder(); }
%#%#%#sphere();
!!difference() { cube(); }
