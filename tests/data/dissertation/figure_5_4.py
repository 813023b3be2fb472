sphere = item[0]
if sphere.prev.ambient[2] == 1.0:
    sphere.parent.setForce(0,100,0)
else:
    sphere.parent.setForce(100,0,0)
