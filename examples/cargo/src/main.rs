//! One fixed scene: when do the two circles touch? (See ../README.md for the scene.)

#[allow(dead_code)]
mod circles {
    include!(concat!(env!("OUT_DIR"), "/circles.rs"));
}

fn main() {
    // x1, y1, vx1, vy1, ax1, ay1, r1, x2, y2, vx2, vy2, ax2, ay2, r2
    let p = [0.0, 0.0, 1.0, 0.0, 0.5, 0.0, 1.0, 10.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.5];
    match circles::first_root(&p, 100.0) {
        Some(t) => println!("collision at t = {t}"),
        None => {
            println!("no collision");
            std::process::exit(1)
        }
    }
}
