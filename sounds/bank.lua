-- The engine's sound bank: every effect and tune the game plays, made by engine/synth from the
-- numbers below (docs/sound.md), so the game ships no sound file and every sound is this
-- repository's own (its licence). A level's own bank (the manifest's `sounds`) adds names or
-- replaces these.
return {
  effects = {
    -- The player.
    jump = { wave = "square", duty = 0.25, frequency = 280, slide_to = 620, attack = 0.002, sustain = 0.04,
             decay = 0.11, lowpass = 5000, volume = 0.32 },
    land = { wave = "noise", frequency = 160, slide_to = 70, attack = 0.001, sustain = 0.01, decay = 0.07,
             lowpass = 1600, volume = 0.45 },
    cross = { wave = "noise", frequency = 500, slide_to = 2000, attack = 0.06, sustain = 0.04, decay = 0.2,
              lowpass = 2200, volume = 0.22 },
    death = { wave = "saw", frequency = 440, slide_to = 55, attack = 0.002, sustain = 0.08, punch = 0.5,
              decay = 0.42, vibrato_depth = 0.08, vibrato_rate = 18, lowpass = 2800, volume = 0.38 },
    respawn = { wave = "triangle", frequency = 330, slide_to = 880, attack = 0.01, sustain = 0.08, decay = 0.18,
                volume = 0.4 },
    -- The level.
    checkpoint = { wave = "square", duty = 0.5, frequency = 660, attack = 0.002, sustain = 0.14, decay = 0.25,
                   arpeggio_at = 0.07, arpeggio_ratio = 1.5, lowpass = 6000, volume = 0.26 },
    switch = { wave = "square", duty = 0.15, frequency = 1200, slide_to = 900, attack = 0.001, sustain = 0.02,
               decay = 0.05, arpeggio_at = 0.02, arpeggio_ratio = 1.33, volume = 0.3 },
    door = { wave = "noise", frequency = 90, slide_to = 55, attack = 0.02, sustain = 0.22, decay = 0.28,
             lowpass = 500, volume = 0.55 },
    goal = { wave = "square", duty = 0.5, frequency = 523.25, attack = 0.002, sustain = 0.32, punch = 0.3,
             decay = 0.6, arpeggio_at = 0.12, arpeggio_ratio = 2, vibrato_depth = 0.01, vibrato_rate = 6,
             lowpass = 5000, volume = 0.3 },
    -- The menus.
    menu_move = { wave = "square", duty = 0.5, frequency = 880, attack = 0.001, sustain = 0.01, decay = 0.03,
                  lowpass = 4000, volume = 0.18 },
    menu_select = { wave = "square", duty = 0.5, frequency = 660, attack = 0.001, sustain = 0.05, decay = 0.1,
                    arpeggio_at = 0.04, arpeggio_ratio = 1.5, lowpass = 5000, volume = 0.24 },
  },
  music = {
    -- The title screen: C, A minor, F, G, slow.
    title = { tempo = 84, voices = {
      { wave = "triangle", volume = 0.3, attack = 0.05, release = 0.3,
        notes = "C2 - - - - - - - A1 - - - - - - -   F1 - - - - - - - G1 - - - - - - -" },
      { wave = "sine", volume = 0.16, decay = 0.25, pan = 0.25,
        notes = "C4 E4 G4 C5 G4 E4 C4 E4 A3 C4 E4 A4 E4 C4 A3 C4   F3 A3 C4 F4 C4 A3 F3 A3 G3 B3 D4 G4 D4 B3 G3 B3" },
      { wave = "triangle", volume = 0.16, attack = 0.04, release = 0.25, pan = -0.2,
        notes = "E5 - - - D5 - C5 - E5 - - - - - - -   F5 - - - E5 - D5 - D5 - - - - - - -" },
    } },
    -- The cube and the tetrahedron: C major, unhurried.
    first_steps = { tempo = 100, voices = {
      { wave = "triangle", volume = 0.32, release = 0.05,
        notes = "C2 - - - . . C2 . G1 - - - . . G1 .   A1 - - - . . A1 . F1 - - - . . G1 ." },
      { wave = "square", duty = 0.25, volume = 0.09, attack = 0.01, release = 0.08, pan = -0.2,
        notes = [[E4 - G4 - C5 - - - B4 - G4 - D4 - - -   C4 - E4 - A4 - - - G4 - F4 - E4 - D4 -
                  E4 - G4 - C5 - - - D5 - B4 - G4 - - -   A4 - - - F4 - D4 - C4 - - - . . . .]] },
      { wave = "noise", volume = 0.05, decay = 0.03, pan = 0.3, notes = ". . C6 . . . C6 . . . C6 . . . C6 ." },
    } },
    -- The octahedron and the dodecahedron: A minor, moving.
    orbit = { tempo = 116, voices = {
      { wave = "triangle", volume = 0.34, release = 0.03,
        notes = "A1 . A1 . A2 . A1 . F1 . F1 . F2 . F1 .   C2 . C2 . C3 . C2 . G1 . G1 . G2 . B1 ." },
      { wave = "square", duty = 0.125, volume = 0.05, release = 0.02, pan = 0.35,
        notes = "A3 C4 E4 A4 E4 C4 A3 C4 F3 A3 C4 F4 C4 A3 F3 A3   C4 E4 G4 C5 G4 E4 C4 E4 G3 B3 D4 G4 D4 B3 G3 B3" },
      { wave = "triangle", volume = 0.2, attack = 0.02, release = 0.1, pan = -0.25,
        notes = [[E5 - - - D5 - C5 - A4 - - - . . . .   G4 - - - C5 - D5 - E5 - - - D5 - B4 -
                  C5 - - - B4 - A4 - F4 - - - . . A4 -   G4 - - - B4 - D5 - C5 - B4 - G4 - - -]] },
      { wave = "sine", volume = 0.45, decay = 0.07, notes = "C2 . . . . . . . C2 . . . . . . ." },
      { wave = "noise", volume = 0.04, decay = 0.025, notes = ". . C7 . . . C7 . . . C7 . . . C7 C7" },
    } },
    -- The icosahedron: E minor, quick.
    crystal = { tempo = 132, voices = {
      { wave = "triangle", volume = 0.32, release = 0.02,
        notes = "E2 . E2 E2 . E2 . E2 C2 . C2 C2 . C2 . C2   D2 . D2 D2 . D2 . D2 B1 . B1 B1 . B1 . D2" },
      { wave = "square", duty = 0.25, volume = 0.08, release = 0.04, decay = 0.25, pan = 0.2,
        notes = [[B4 . E5 . G5 . F#5 . E5 . . . B4 . . .   C5 . E5 . G5 . A5 . G5 . F#5 . E5 . D5 .
                  D5 . F#5 . A5 . G5 . F#5 . . . D5 . . .   B4 . D5 . F#5 . E5 . D#5 . . . . . . .]] },
      { wave = "sine", volume = 0.45, decay = 0.06, notes = "C2 . . . C2 . . . C2 . . . C2 . . ." },
      { wave = "noise", volume = 0.045, decay = 0.02, pan = -0.3, notes = ". C7 . C7 . C7 . C7 . C7 . C7 . C7 . C7" },
    } },
    -- The mesh stages: D dorian, slow and airy.
    lattice = { tempo = 92, voices = {
      { wave = "sine", volume = 0.3, attack = 0.05, release = 0.2,
        notes = "D2 - - - - - - - . . . . A1 - - -   C2 - - - - - - - . . . . G1 - - -" },
      { wave = "triangle", volume = 0.1, attack = 0.3, release = 0.4, pan = -0.3,
        notes = "A4 - - - - - - - - - - - - - - -   G4 - - - - - - - - - - - - - - -" },
      { wave = "triangle", volume = 0.08, attack = 0.3, release = 0.4, pan = 0.3,
        notes = "F4 - - - - - - - - - - - - - - -   E4 - - - - - - - - - - - - - - -" },
      { wave = "sine", volume = 0.2, decay = 0.35,
        notes = "D5 . . A5 . . F5 . . . E5 . C5 . . .   D5 . . G5 . . E5 . . . C5 . A4 . . ." },
    } },
  },
}
