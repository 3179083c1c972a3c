// Two root modifiers: the first wins, the second warns
!sphere();
!cube();
