#%!*#%!*cube();
!!!!!!!!sphere();
%%%%%%%%%%%%cylinder();
**cube();
