// A root inside the root is a plain part of it, and no second root
!union() { !cube(); sphere(); }
echo(1);
!cylinder();
