angle increment: 45
initial line width: 1 pixels
