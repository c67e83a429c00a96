//! Exact integer helpers: 256-bit products, integer square roots rounded half up, quotients
//! rounded half up, and the tangent table (COM.UNITS rounding, G76.INFEED.Z, G76.PULLOUT).
//!
//! Every function is total: no panics, no overflow, no floating point.

/// An unsigned 256-bit integer, `hi · 2^128 + lo`. The derived order compares `hi` first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct U256 {
    pub hi: u128,
    pub lo: u128,
}

impl U256 {
    pub const fn from_u128(v: u128) -> U256 {
        U256 { hi: 0, lo: v }
    }

    /// `self · m`, or `None` when the product does not fit 256 bits.
    pub fn checked_mul_u64(self, m: u64) -> Option<U256> {
        let low = mul_wide(self.lo, u128::from(m));
        let hi = self.hi.checked_mul(u128::from(m))?.checked_add(low.hi)?;
        Some(U256 { hi, lo: low.lo })
    }
}

const LOW64: u128 = (1u128 << 64) - 1;

/// The exact product of two `u128` as a [`U256`].
pub fn mul_wide(a: u128, b: u128) -> U256 {
    let (a1, a0) = (a >> 64, a & LOW64);
    let (b1, b0) = (b >> 64, b & LOW64);
    // Each partial product of two 64-bit halves is below 2^128.
    let p00 = a0 * b0;
    let p01 = a0 * b1;
    let p10 = a1 * b0;
    let p11 = a1 * b1;
    // mid < 3 · 2^64.
    let mid = (p00 >> 64) + (p01 & LOW64) + (p10 & LOW64);
    let lo = (p00 & LOW64) | ((mid & LOW64) << 64);
    // The full product is below 2^256, so the high half cannot overflow.
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    U256 { hi, lo }
}

/// ⌊√n⌋: core's integer square root (exact; a 64-bit root when n fits 64 bits, which is the
/// common case of the depth schedule and several times faster than the 128-bit one).
pub fn isqrt(n: u128) -> u128 {
    match u64::try_from(n) {
        Ok(small) => u128::from(small.isqrt()),
        Err(_) => n.isqrt(),
    }
}

/// √n rounded half up: r + 1 when n − r² > r, r = ⌊√n⌋ (√n is never exactly r + ½).
pub fn sqrt_round(n: u128) -> u128 {
    let r = isqrt(n);
    // r² ≤ n, so neither the square nor the difference overflows.
    if n - r * r > r {
        r + 1
    } else {
        r
    }
}

/// `v` as `i64`, saturating toward its sign. Legal words keep every coordinate far inside
/// `i64`; this keeps an out-of-range intermediate from wrapping.
pub fn sat(v: i128) -> i64 {
    i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}

/// `num / den` rounded half up; `den = 0` gives 0 (callers never divide by zero).
pub fn div_round(num: u128, den: u128) -> u128 {
    if den == 0 {
        return 0;
    }
    // Both within 64 bits (every division of legal words): one hardware division.
    let (q, r) = match (u64::try_from(num), u64::try_from(den)) {
        (Ok(n), Ok(d)) => (u128::from(n / d), u128::from(n % d)),
        _ => (num / den, num % den),
    };
    // r < den; the quotient rounds up when 2r ≥ den, written without overflow.
    if r >= den - r {
        q + 1
    } else {
        q
    }
}

/// `num / den` for signed values, rounded half up on the magnitude (half away from zero).
pub fn div_round_signed(num: i128, den: i128) -> i128 {
    let mag = div_round(num.unsigned_abs(), den.unsigned_abs());
    // mag ≤ |num| ≤ 2^127, and it is only negated.
    let mag = i128::try_from(mag).unwrap_or(i128::MAX);
    if (num < 0) != (den < 0) {
        -mag
    } else {
        mag
    }
}

/// Fractional bits of the tangent table.
pub const TAN_FRAC_BITS: u32 = 128;

/// The largest index of [`tan_half_degrees`]: 178 half degrees = 89°.
pub const TAN_MAX_INDEX: u32 = 178;

/// `tan(h · 0.5°)` for h = 0…178 as (integer part, ⌊fraction · 2^128⌋), computed offline with
/// 120 significant digits. Exact at 0° and 45°; everywhere else tan is irrational and the table
/// value lies strictly within 2^-128 below it.
///
/// Decision margin (checked offline by continued fractions of 2·tan): for every entry except
/// 0° and 45°, and every 1 ≤ δ ≤ 2·10^9, |δ·tan − (m + ½)| ≥ 3.2·10^-12 for all integers m,
/// while the table's error on δ·tan is below δ·2^-128 < 10^-29. So the rounding of δ·tan is
/// decided exactly by the table for every δ ≤ 10^9 (and far beyond).
const TAN_TABLE: [(u8, u128); 179] = [
    (0, 0x00000000000000000000000000000000), // tan(0.0°)
    (0, 0x023bec8bc200cde0791a9f517decb003), // tan(0.5°)
    (0, 0x0477ef650429088631c8488375bc5259), // tan(1.0°)
    (0, 0x06b41edcc159f496e282f0cb8c9c6920), // tan(1.5°)
    (0, 0x08f0914aeb0fe10671c00a79f9a2a78c), // tan(2.0°)
    (0, 0x0b2d5d11e792b6c0684e4b9ff1a5c18a), // tan(2.5°)
    (0, 0x0d6a98a2139f39107fb67b86a8f97714), // tan(3.0°)
    (0, 0x0fa85a7d48b444fb55c2c16cc3b7d093), // tan(3.5°)
    (0, 0x11e6b93a693203f88a511cd4dd8f82a0), // tan(4.0°)
    (0, 0x1425cb88f37c5aa28c2176b648b93ed5), // tan(4.5°)
    (0, 0x1665a8349d55e0dfc3a230adb295a89f), // tan(5.0°)
    (0, 0x18a66628f8ad6a4b4cf4ee8c77824d77), // tan(5.5°)
    (0, 0x1ae81c75231d9761269f4b83b9a6ef3f), // tan(6.0°)
    (0, 0x1d2ae24f816416f95ac199f17a8ea278), // tan(6.5°)
    (0, 0x1f6ecf19881d316a992ef7dd1f6444b2), // tan(7.0°)
    (0, 0x21b3fa639317f16df1b90e5aa6880a9c), // tan(7.5°)
    (0, 0x23fa7bf0cc9fc97d43965925d0199a32), // tan(8.0°)
    (0, 0x26426bbb2621f6932a78275940e05d1f), // tan(8.5°)
    (0, 0x288be1f7639f236a6d65b8bc85bc2f70), // tan(9.0°)
    (0, 0x2ad6f7193b64faf1fe1ae3271c3e7b8b), // tan(9.5°)
    (0, 0x2d23c3d78b9777dc697adcb5d3105e92), // tan(10.0°)
    (0, 0x2f726130a71edd2bc1637e14061267fe), // tan(10.5°)
    (0, 0x31c2e86ebb9d6c8c6c45726f08ab6b81), // tan(11.0°)
    (0, 0x3415732c521f307a5bbfce3249747f6e), // tan(11.5°)
    (0, 0x366a1b58ec4697f0bc5089aae9b10630), // tan(12.0°)
    (0, 0x38c0fb3dbfca3f5edaf524f294b087be), // tan(12.5°)
    (0, 0x3b1a2d82922b27b4861004d65a8f89b3), // tan(13.0°)
    (0, 0x3d75cd32b69edad6d02a17b40c5e3e10), // tan(13.5°)
    (0, 0x3fd3f5c2303ea87b03e62c7509ef03a5), // tan(14.0°)
    (0, 0x4234c312faa454a0c233c5a76296bbde), // tan(14.5°)
    (0, 0x4498517a7b3558c4da8bd28f8747c476), // tan(15.0°)
    (0, 0x46febdc71d78535c02adb97a192afa79), // tan(15.5°)
    (0, 0x496825461cec891b5ff26209516365c4), // tan(16.0°)
    (0, 0x4bd4a5c97ef98e1d4b2aa7f3c9c40531), // tan(16.5°)
    (0, 0x4e445dae3fad696ac189af0513322c86), // tan(17.0°)
    (0, 0x50b76be2b421edbc256129becee4298c), // tan(17.5°)
    (0, 0x532defed2586baef1cc09641db560751), // tan(18.0°)
    (0, 0x55a809f2a7f48c36f53d6e5a4bc891aa), // tan(18.5°)
    (0, 0x5825dabe30584a14ac2308f085f79060), // tan(19.0°)
    (0, 0x5aa783c7ecf0fabae42e1f642e7b8edc), // tan(19.5°)
    (0, 0x5d2d273ce40b516d5edb017d831e4a36), // tan(20.0°)
    (0, 0x5fb6e806dcd87b75c325bbb023eb38f7), // tan(20.5°)
    (0, 0x6244e9d496741999cf80685945034cba), // tan(21.0°)
    (0, 0x64d75122516756820e074961cfc95cd8), // tan(21.5°)
    (0, 0x676e4342b0350145bbdbb7b736b42de3), // tan(22.0°)
    (0, 0x6a09e667f3bcc908b2fb1366ea957d3e), // tan(22.5°)
    (0, 0x6caa61ad988a7b10635b5156fd02b49e), // tan(23.0°)
    (0, 0x6f4fdd225a71ce64efbf74d22f919d7d), // tan(23.5°)
    (0, 0x71fa81d2a42834b74a932504720e7754), // tan(24.0°)
    (0, 0x74aa79d370e4bd868cf6e69682817d85), // tan(24.5°)
    (0, 0x775ff04da66ac4b001df31557c709db4), // tan(25.0°)
    (0, 0x7a1b1189ee47607eb217c44067599313), // tan(25.5°)
    (0, 0x7cdc0afd1573cf11126eeb54e2d8e2df), // tan(26.0°)
    (0, 0x7fa30b54fa010cf80375baed46b7ae70), // tan(26.5°)
    (0, 0x827042860eeae120f23114634422f238), // tan(27.0°)
    (0, 0x8543e1d97eb3abda1463e8e5fd79fb8a), // tan(27.5°)
    (0, 0x881e1bfbf5f6de5cf673d6f6a13e898a), // tan(28.0°)
    (0, 0x8aff250d1fb6f472dea2f9ece2a3e66d), // tan(28.5°)
    (0, 0x8de732afddcdf31578745346f7680b95), // tan(29.0°)
    (0, 0x90d67c1b4895b9bd277c995bb366eb97), // tan(29.5°)
    (0, 0x93cd3a2c8198e2690c7c0f257d92be83), // tan(30.0°)
    (0, 0x96cba77965e6984219a7152249de666e), // tan(30.5°)
    (0, 0x99d200642d7cea4a08c0aab2d6980eb0), // tan(31.0°)
    (0, 0x9ce083300627001335a1469bd3470000), // tan(31.5°)
    (0, 0x9ff77016b928ab4ce54797b4d36e948a), // tan(32.0°)
    (0, 0xa317095f6c20ae9fbcbaccc41a2e814d), // tan(32.5°)
    (0, 0xa63f93768eb074997ea0f466633c28b1), // tan(33.0°)
    (0, 0xa971550707b4bf26c797ce024c6e7f51), // tan(33.5°)
    (0, 0xacac9714b63128178ae7b7bc9599fb77), // tan(34.0°)
    (0, 0xaff1a5185b82692e6649f6af4974e2e7), // tan(34.5°)
    (0, 0xb340cd1d05fbd4d78c7912fc8bc40fbc), // tan(35.0°)
    (0, 0xb69a5fdf14c5f7b41faa7ed469115b41), // tan(35.5°)
    (0, 0xb9feb0ecefaa170af5086c5d75b89e2f), // tan(36.0°)
    (0, 0xbd6e16c98f7389f0e49f6906900dcb54), // tan(36.5°)
    (0, 0xc0e8eb10f5b87d6bbca03749271dd0c2), // tan(37.0°)
    (0, 0xc46f8a9eb533add2d6ab426dc2cd8732), // tan(37.5°)
    (0, 0xc80255b6ae648fb5cd685e00ffd68228), // tan(38.0°)
    (0, 0xcba1b03026f053ab0918a41a338088d6), // tan(38.5°)
    (0, 0xcf4e01a36541b8e29bc7e9c3a441b252), // tan(39.0°)
    (0, 0xd307b599fd2df44edaaae4379f96539e), // tan(39.5°)
    (0, 0xd6cf3bc1fdf8ee388a2895d17c68d59c), // tan(40.0°)
    (0, 0xdaa5082435fa626052b4525e9e88155f), // tan(40.5°)
    (0, 0xde89935dc4688731bfc259b6ec24604d), // tan(41.0°)
    (0, 0xe27d5add36753d95e4cb5f7c0ddf1791), // tan(41.5°)
    (0, 0xe680e1237202f8cf09cc758f4958ae1a), // tan(42.0°)
    (0, 0xea94ae08b5ca5147896e51fbda0212c4), // tan(42.5°)
    (0, 0xeeb94f05fce5b3cc64de0b3ccbe24880), // tan(43.0°)
    (0, 0xf2ef57831a6c8bc24b594e5d374943b0), // tan(43.5°)
    (0, 0xf7376129e92317fa773df599be43c493), // tan(44.0°)
    (0, 0xfb920c3ef35a41b16a95b4431c978a1e), // tan(44.5°)
    (1, 0x00000000000000000000000000000000), // tan(45.0°)
    (1, 0x0481eb08fbac52bdce26454a08102ed1), // tan(45.5°)
    (1, 0x091883bfbf42da075abe0a8db18913ad), // tan(46.0°)
    (1, 0x0dc488c741aafde34ac6456a893c31d9), // tan(46.5°)
    (1, 0x1286c17acf49bbbd798044e687014dc0), // tan(47.0°)
    (1, 0x175ffe71f076130710b2b3573f2d6403), // tan(47.5°)
    (1, 0x1c511a0db83e2791570b0c96bca68c98), // tan(48.0°)
    (1, 0x215af91046afa06b17294f364ca7a0f6), // tan(48.5°)
    (1, 0x267e8b3f5da81a2c46ef0c028c5794b3), // tan(49.0°)
    (1, 0x2bbccc12fd38a9352d7fc3d7aa007440), // tan(49.5°)
    (1, 0x3116c3711527ddf15d1e4f3d228992c0), // tan(50.0°)
    (1, 0x368d86777468cd67b335c915b0ed2aa2), // tan(50.5°)
    (1, 0x3c2238553dcee8c41468fd1977a3beb3), // tan(51.0°)
    (1, 0x41d60b354b46a3141538adc6e89f9c3d), // tan(51.5°)
    (1, 0x47aa413b0ee1e0abd534b6eb13b48973), // tan(52.0°)
    (1, 0x4da02d93ab9e5f5c8bc2e78cd15d1020), // tan(52.5°)
    (1, 0x53b9359d2f918fa27c84fb5bc9e49c4a), // tan(53.0°)
    (1, 0x59f6d2260ece5cc667b2c710b6722460), // tan(53.5°)
    (1, 0x605a90c73ab78ce92e8998e12c64acd2), // tan(54.0°)
    (1, 0x66e6155b75768bdd77f090b575007c02), // tan(54.5°)
    (1, 0x6d9b1b96ce1277b24a2f15f79200a428), // tan(55.0°)
    (1, 0x747b78c1886a9c62054ac761d37b7c5c), // tan(55.5°)
    (1, 0x7b891d9a169b2aa3029f272b0302573f), // tan(56.0°)
    (1, 0x82c6186238c9b5478e4e70b04673e88e), // tan(56.5°)
    (1, 0x8a34971bd700de0813c73e6f4759175a), // tan(57.0°)
    (1, 0x91d6e9fab8f637ffc0792f6f130fbcb7), // tan(57.5°)
    (1, 0x99af8610e410496f0a256e5e99205a48), // tan(58.0°)
    (1, 0xa1c1083c23fcc2551a036f625b8ce470), // tan(58.5°)
    (1, 0xaa0e385c196aa703f5a858a0191521c6), // tan(59.0°)
    (1, 0xb29a0cd921827e6d0a8fbbb038ae7d99), // tan(59.5°)
    (1, 0xbb67ae8584caa73b25742d7078b83b89), // tan(60.0°)
    (1, 0xc47a7ce3a38f8e5138fdeec1609708f8), // tan(60.5°)
    (1, 0xcdd612dd501f49af430382b09e4534aa), // tan(61.0°)
    (1, 0xd77e4bfa3d17dda5dbe4e2b9a91c37d1), // tan(61.5°)
    (1, 0xe1774a2562592e8c0c43466fcc72807a), // tan(62.0°)
    (1, 0xebc57c138aab55892d560edf15021b03), // tan(62.5°)
    (1, 0xf66da45fee3f0f36dc41ed1e2f942e97), // tan(63.0°)
    (2, 0x0174e176e57207cf7cb6297f94f34ff5), // tan(63.5°)
    (2, 0x0ce0b66a723cee7cad3fa756e285e72f), // tan(64.0°)
    (2, 0x18b714d0b8cad243e9a797c7afdcf7b8), // tan(64.5°)
    (2, 0x24fe67d1a25ca12116305cf8754248ed), // tan(65.0°)
    (2, 0x31bda08ef9b5cbea0c7b9a045aca3e20), // tan(65.5°)
    (2, 0x3efc4419882e26555e2c102304bfd388), // tan(66.0°)
    (2, 0x4cc27b2e543d35fdb97b8b4bc7562e7d), // tan(66.5°)
    (2, 0x5b1924016ad0ab0551d73c8a798a3dc6), // tan(67.0°)
    (2, 0x6a09e667f3bcc908b2fb1366ea957d3e), // tan(67.5°)
    (2, 0x799f4ac22ebab5547157ccd299c6553d), // tan(68.0°)
    (2, 0x89e4d417effacdfd0107d32eddcbf859), // tan(68.5°)
    (2, 0x9ae71df006f068bc7d968186be5065eb), // tan(69.0°)
    (2, 0xacb3fe859828afce5103d3b53c9a625f), // tan(69.5°)
    (2, 0xbf5aae1f0e5b0d5019179ff7c8316fb7), // tan(70.0°)
    (2, 0xd2ebf472688ecc430d0019971dc30c42), // tan(70.5°)
    (2, 0xe77a5d344e1c0b6c568c76c6ad60a347), // tan(71.0°)
    (2, 0xfd1a752d0717ab7bee476511df91ca40), // tan(71.5°)
    (3, 0x13e3117b9af5d4c179d3c804341f60f7), // tan(72.0°)
    (3, 0x2beda3105046dd20b9bf55adf2e571dd), // tan(72.5°)
    (3, 0x455698e26ce3beb0c6c7fd5b1936db04), // tan(73.0°)
    (3, 0x603dd4012cfb4a2d72b924d2587633e7), // tan(73.5°)
    (3, 0x7cc73167e50d1bf9743d3ec683a41a55), // tan(74.0°)
    (3, 0x9b1b2e7f504da163edfe6aba4b553e06), // tan(74.5°)
    (3, 0xbb67ae8584caa73b25742d7078b83b89), // tan(75.0°)
    (3, 0xdde0e8cd9ae2e7ff483acb089f212532), // tan(75.5°)
    (4, 0x02c28a0cf4f105931c6cb954a2d4049a), // tan(76.0°)
    (4, 0x2a5115f2931cf94488adf1f06b869b40), // tan(76.5°)
    (4, 0x54db9a5776a504ade08f53841f9b5812), // tan(77.0°)
    (4, 0x82bdcae1048381a10755dee37f351999), // tan(77.5°)
    (4, 0xb462a38bfca2e49b78a8a9f0f330ad41), // tan(78.0°)
    (4, 0xea47bb2f27c08684ff6e47473c88fafb), // tan(78.5°)
    (5, 0x25017df31912d7354ef50c143c3815fd), // tan(79.0°)
    (5, 0x65409d10b4ffaea4bc90812182b333d5), // tan(79.5°)
    (5, 0xabd92015a84d927c9baa1ca563733e01), // tan(80.0°)
    (5, 0xf9cbb181d79d11caab33d0b476ffc21a), // tan(80.5°)
    (6, 0x505204ee998acced610d48c4edfaf15f), // tan(81.0°)
    (6, 0xb0ef9d7fffe973f4b808220f734e1328), // tan(81.5°)
    (7, 0x1d88dec096ba01702c10d6b2d761cede), // tan(82.0°)
    (7, 0x9883576e9cad3fe43ca1693b97f881af), // tan(82.5°)
    (8, 0x24f3e33371ff3c90d2086a86650c4de6), // tan(83.0°)
    (8, 0xc6e216fe6eae20551be040f9b9c5529e), // tan(83.5°)
    (9, 0x83ad638d1c63609817f09f65a00849c2), // tan(84.0°)
    (10, 0x62a9620f2ad318b5eadf06b4eff27971), // tan(84.5°)
    (11, 0x6e17e85fedf105d8faf669f8797c24a2), // tan(85.0°)
    (12, 0xb4c9d5662691f47d4e3c084024af2195), // tan(85.5°)
    (14, 0x4cf876bb96a606d8e272ca3a8c53205c), // tan(86.0°)
    (16, 0x599020e42cb2be1cf9d396798dd06c61), // tan(86.5°)
    (19, 0x14c55fbc4c65fa40af97ba51e90a0a98), // tan(87.0°)
    (22, 0xe75d2dd1c374c2725e3b1f90e49e0acf), // tan(87.5°)
    (28, 0xa2e17ec2185beeb836a59eef1248e845), // tan(88.0°)
    (38, 0x303ede555a25e91841b2656f5eb07e52), // tan(88.5°)
    (57, 0x4a3aece934e0e5f69f1386619a4e22e5), // tan(89.0°)
];

/// `tan(h · 0.5°)` as (integer part, fraction · 2^128 rounded down); `None` beyond 89°.
pub fn tan_half_degrees(h: u32) -> Option<(u8, u128)> {
    TAN_TABLE.get(usize::try_from(h).ok()?).copied()
}

/// tan(h · 0.5°) from the tangent table ([`tan_half_degrees`]), looked up once where many
/// depths are multiplied by it (G76.INFEED.Z: every pass).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tan {
    int: u8,
    /// The fraction · 2^128 as two halves (8-byte alignment keeps the cycle state small).
    frac: [u64; 2],
}

impl Tan {
    /// tan 0: every product is 0.
    pub const ZERO: Tan = Tan { int: 0, frac: [0; 2] };

    /// tan(h · 0.5°); `None` when h > 178 (beyond 89°).
    pub fn half_degrees(h: u32) -> Option<Tan> {
        tan_half_degrees(h).map(|(int, frac)| Tan { int, frac: [(frac >> 64) as u64, frac as u64] })
    }

    /// δ · tan rounded half up, and whether the table's enclosure decides the rounding (always
    /// true for δ ≤ 10^9, see `TAN_TABLE`'s margin). `None` when the result does not fit `u64`.
    pub fn mul_checked(self, delta: u64) -> Option<(u64, bool)> {
        let frac = u128::from(self.frac[0]) << 64 | u128::from(self.frac[1]);
        let x = mul_wide(u128::from(delta), frac);
        // δ·tan ∈ [δ·int + x/2^128, δ·int + (x + δ)/2^128). Rounding half up adds 1 when the
        // fraction x.lo / 2^128 is at least one half. x.hi < δ and int < 2^8: no overflow.
        let up = x.lo >> 127;
        let whole = u128::from(delta) * u128::from(self.int) + x.hi + up;
        // The rounding is decided when x.lo + δ does not cross the next half-integer boundary.
        let shifted = x.lo ^ (1u128 << 127); // distance above the last boundary, mod 2^128
        let decided = frac == 0 || shifted.checked_add(u128::from(delta)).is_some();
        Some((u64::try_from(whole).ok()?, decided))
    }

    /// δ · tan rounded half up; saturates at `u64::MAX` where it does not fit.
    pub fn times(self, delta: u64) -> u64 {
        self.mul_checked(delta).map_or(u64::MAX, |(v, _)| v)
    }
}

/// δ · tan(h · 0.5°) rounded half up, and whether the table's enclosure decides the rounding
/// ([`Tan::mul_checked`]). `None` when h > 178 or the result does not fit `u64`.
pub fn mul_tan_checked(delta: u64, h: u32) -> Option<(u64, bool)> {
    Tan::half_degrees(h)?.mul_checked(delta)
}

/// δ · tan(h · 0.5°) rounded half up (G76.INFEED.Z, G76.PULLOUT); saturates at `u64::MAX`
/// where it does not fit, 0 when h > 178.
pub fn mul_tan(delta: u64, h: u32) -> u64 {
    Tan::half_degrees(h).map_or(0, |t| t.times(delta))
}

/// The spindle start angle of start `j` of `l`, in 0.001°: round(360 000 · j / l)
/// (COM.MULTISTART). `l = 0` gives 0.
pub fn start_angle(j: u32, l: u32) -> u32 {
    let v = div_round(360_000u128 * u128::from(j), u128::from(l));
    u32::try_from(v).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn sat_saturates_toward_the_sign() {
        assert_eq!(sat(i128::MAX), i64::MAX);
        assert_eq!(sat(i128::MIN), i64::MIN);
        assert_eq!(sat(i128::from(i64::MAX) + 1), i64::MAX);
        assert_eq!(sat(i128::from(i64::MIN) - 1), i64::MIN);
        assert_eq!((sat(-7), sat(0), sat(7)), (-7, 0, 7));
    }

    #[test]
    fn mul_wide_matches_small_products() {
        assert_eq!(mul_wide(3, 5), U256 { hi: 0, lo: 15 });
        assert_eq!(mul_wide(u128::MAX, u128::MAX), U256 { hi: u128::MAX - 1, lo: 1 });
        assert_eq!(mul_wide(1u128 << 127, 2), U256 { hi: 1, lo: 0 });
        let x = (1u128 << 100) + 12345;
        let y = (1u128 << 90) + 777;
        // (2^100 + a)(2^90 + b) = 2^190 + b·2^100 + a·2^90 + ab
        let p = mul_wide(x, y);
        assert_eq!(p.hi, 1u128 << 62);
        assert_eq!(p.lo, (777u128 << 100) + (12345u128 << 90) + 12345 * 777);
        assert_eq!(U256 { hi: 1, lo: 0 }.checked_mul_u64(3), Some(U256 { hi: 3, lo: 0 }));
        assert_eq!(U256 { hi: u128::MAX, lo: 0 }.checked_mul_u64(2), None);
    }

    #[test]
    fn square_roots() {
        for n in 0u128..10_000 {
            let r = isqrt(n);
            assert!(r * r <= n && (r + 1) * (r + 1) > n, "{n}");
            let rr = sqrt_round(n);
            // round half up: rr - 1/2 <= sqrt(n) < rr + 1/2  <=>  (2rr-1)^2 <= 4n < (2rr+1)^2
            assert!((2 * rr).saturating_sub(1).pow(2) <= 4 * n && 4 * n < (2 * rr + 1).pow(2), "{n}");
        }
        assert_eq!(isqrt(u128::MAX), u128::from(u64::MAX));
        assert_eq!(sqrt_round(u128::MAX), 1u128 << 64);
        // F76.EX1: 0.7 mm · √2 = 0.98995 mm → 990 µm.
        assert_eq!(sqrt_round(2 * 700 * 700), 990);
    }

    #[test]
    fn rounding_quotients() {
        assert_eq!(div_round(5, 2), 3);
        assert_eq!(div_round(7, 3), 2);
        assert_eq!(div_round(8, 3), 3);
        assert_eq!(div_round(u128::MAX, u128::MAX), 1);
        assert_eq!(div_round(1, 0), 0);
        assert_eq!(div_round_signed(-5, 2), -3);
        assert_eq!(div_round_signed(5, -2), -3);
        assert_eq!(div_round_signed(-4, 3), -1);
        // Across the 64-bit fast path's edges: each side, and a numerator or a denominator
        // just beyond 64 bits.
        let big = u128::from(u64::MAX);
        assert_eq!(div_round(big, 2), big / 2 + 1);
        assert_eq!(div_round(big + 1, 2), 1 << 63);
        assert_eq!(div_round(big + 3, big + 1), 1);
        assert_eq!(div_round((big + 1) * 3 + big / 2 + 1, big + 1), 4);
        assert_eq!(div_round(3 * big + big / 2, big), 3);
        assert_eq!(div_round(3 * big + big / 2 + 1, big), 4);
    }

    #[test]
    fn tangents() {
        assert_eq!(mul_tan(1_000_000, 0), 0);
        assert_eq!(mul_tan(123_457, 90), 123_457); // tan 45° = 1
        // tan 30° = 0.577350269…
        assert_eq!(mul_tan(1_000_000, 60), 577_350);
        assert_eq!(mul_tan(1_000, 60), 577);
        // tan 89° = 57.28996163…
        assert_eq!(mul_tan(1_000_000, 178), 57_289_962);
        // tan 22.5° = √2 − 1 = 0.41421356237…
        assert_eq!(mul_tan(100_000_000, 45), 41_421_356);
        assert_eq!(mul_tan(1, 179), 0);
        assert_eq!(mul_tan(u64::MAX, 178), u64::MAX);
        // Decided for a spread of δ up to 10^9 on every entry.
        let mut d = 1u64;
        while d <= 1_000_000_000 {
            for h in 0..=TAN_MAX_INDEX {
                for dd in [d, d + 1, d * 3 + 7] {
                    let (_, ok) = mul_tan_checked(dd, h).unwrap();
                    assert!(ok, "h {h} d {dd}");
                }
            }
            d = d * 7 + 3;
        }
    }

    #[test]
    fn tan_table_monotone() {
        for h in 1..=TAN_MAX_INDEX {
            assert!(tan_half_degrees(h - 1) < tan_half_degrees(h));
        }
        assert_eq!(tan_half_degrees(90), Some((1, 0)));
    }

    #[test]
    fn angles() {
        assert_eq!(start_angle(0, 3), 0);
        assert_eq!(start_angle(1, 3), 120_000);
        assert_eq!(start_angle(1, 7), 51_429); // 51428.57…
        assert_eq!(start_angle(1, 16), 22_500);
        assert_eq!(start_angle(998, 999), 359_640); // 359639.63…
        assert_eq!(start_angle(1, 0), 0);
    }
}
