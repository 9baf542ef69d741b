#[test]
fn scratch() {
    let o = trace::LoadOptions { width: 640, height: 480, ..Default::default() };
    let p = std::path::Path::new("/tmp/lat/spheres100k.rt");
    let a = trace::load(p, &o).unwrap().scene;
    let text = std::fs::read_to_string(p).unwrap().replace("<30, 60, -40>", "<31, 60, -40>");
    let b = trace::load_str(p, text, &o).unwrap().scene;
    let cache = trace::BuildCache::default();
    let t = std::time::Instant::now();
    let mut prep = trace::prepare(&a, None, &cache).unwrap();
    eprintln!("first {:?}", t.elapsed());
    for i in 0..20 {
        let t = std::time::Instant::now();
        let (p2, r) = if i % 2 == 0 { prep.rebuild(&b, &a, &cache) } else { prep.rebuild(&a, &b, &cache) };
        prep = p2;
        eprintln!("rebuild {:?} {r:?}", t.elapsed());
    }
}
