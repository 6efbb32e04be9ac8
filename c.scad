use </work/main/.venv/lib/python3.11/site-packages/matplotlib/mpl-data/fonts/ttf/DejaVuSans.ttf>
linear_extrude(1) text("gjq", size=10, font="DejaVu Sans", halign="left", valign="bottom");
