angle increment: 10
line style: cylinder
viewpoint: 1,0.3,1
view reference point: 0,0,0
projection: perspective
