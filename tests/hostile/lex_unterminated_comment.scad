cube();
/* this comment never ends
sphere();
